// The shadow method's one name table: every method's name spells it back, and the nodes' method
// fields read and write the same names for the same values.
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/ShadowMethod.h"
#include "ivshadow/SoDeepShadowDirectionalLight.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoDeepShadowSpotLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene/CoinRef.h"

#include <Inventor/SbString.h>
#include <Inventor/fields/SoSFEnum.h>

#include <gtest/gtest.h>

#include <iterator>
#include <set>
#include <string>

namespace ivshadow {
namespace {

constexpr ShadowMethod kMethods[] = {ShadowMethod::Auto, ShadowMethod::Map, ShadowMethod::Rays,
                                     ShadowMethod::Volumes, ShadowMethod::OpacityMap};

TEST(ShadowMethod, EveryMethodsNameSpellsItBack) {
  static_assert(std::size(kMethods) == kShadowMethodCount);
  std::set<std::string> names;
  for (const ShadowMethod method : kMethods) {
    const char* name = shadowMethodName(method);
    EXPECT_EQ(shadowMethodNamed(name), method) << name;
    names.insert(name);
  }
  EXPECT_EQ(names.size(), kShadowMethodCount) << "two methods share a name";
  EXPECT_FALSE(shadowMethodNamed("AUTO_METHOD").has_value());
  EXPECT_FALSE(shadowMethodNamed("rays").has_value());
  EXPECT_FALSE(shadowMethodNamed("").has_value());
}

TEST(ShadowMethod, ResolvedMethodsThatShadowPerPixelAreRaysAndVolumes) {
  for (const ShadowMethod method : kMethods)
    EXPECT_EQ(shadowsPerPixel(method),
              method == ShadowMethod::Rays || method == ShadowMethod::Volumes)
        << shadowMethodName(method);
}

// Coin's field API, not the table, reads each node's method field.
template <class Node>
void expectMethodFieldSpellsTheTable() {
  init();
  const CoinRef<Node> node(new Node);
  SoSFEnum& field = node->method;
  for (const ShadowMethod method : kMethods) {
    const char* name = shadowMethodName(method);
    ASSERT_TRUE(field.set(name)) << name;
    EXPECT_EQ(field.getValue(), int(method)) << name;
    SbString written;
    field.get(written);
    EXPECT_EQ(std::string(written.getString()), name);
  }
}

TEST(ShadowMethod, TheNodesMethodFieldsReadAndWriteTheTablesNames) {
  expectMethodFieldSpellsTheTable<SoDeepShadowLight>();
  expectMethodFieldSpellsTheTable<SoDeepShadowSpotLight>();
  expectMethodFieldSpellsTheTable<SoDeepShadowDirectionalLight>();
  expectMethodFieldSpellsTheTable<SoTransparentShadowGroup>();
}

}  // namespace
}  // namespace ivshadow
