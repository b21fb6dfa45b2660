#include "scene/InputError.h"
#include "scene_input/TransparencyType.h"

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

TEST(TransparencyType, NamesRoundTripForEveryCoinType) {
  for (int value = SoGLRenderAction::SCREEN_DOOR; value <= SoGLRenderAction::SORTED_LAYERS_BLEND;
       ++value) {
    const auto type = static_cast<SoGLRenderAction::TransparencyType>(value);
    EXPECT_EQ(transparencyTypeFromName(transparencyTypeName(type)), type);
  }
  EXPECT_EQ(transparencyTypeFromName("SORTED_LAYERS_BLEND"), SoGLRenderAction::SORTED_LAYERS_BLEND);
}

TEST(TransparencyType, UnknownNameListsTheValidOnes) {
  try {
    transparencyTypeFromName("sorted_layers");
    FAIL();
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("--transparency 'sorted_layers'"), std::string::npos);
    EXPECT_NE(message.find("SORTED_LAYERS_BLEND"), std::string::npos);
  }
}

}  // namespace
}  // namespace ivshadow
