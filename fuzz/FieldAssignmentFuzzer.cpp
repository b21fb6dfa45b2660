// libFuzzer harness: `--set NAME.field=VALUE` texts (and the same lines of variants files)
// against the three nodes, followed by the light's settings resolution that every frame
// runs on whatever the fields hold.
#include "fuzz/FuzzInput.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "nodes/DeepShadowSettings.h"
#include "scene/InputError.h"
#include "scene_input/FieldAssignment.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cstring>

namespace {

const char kScene[] =
    "#Inventor V2.1 ascii\n"
    "DEF Group TransparentShadowGroup { DEF Lamp DeepShadowLight { location 0 0 4 }\n"
    "  DEF Peel PeelingSeparator { DEF Glass Material { transparency 0.5 } Cube { } } }\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ivshadow::fuzz::initOnce();
  SoInput input;
  input.setBuffer(kScene, sizeof(kScene) - 1);
  SoSeparator* root = SoDB::readAll(&input);
  if (root == nullptr) __builtin_trap();  // the fixed scene must read
  root->ref();
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    ivshadow::FieldAssignment::parse(text).apply(root, "fuzz.iv");
  } catch (const ivshadow::InputError&) {
  }
  auto* light = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
  ivshadow::resolveSettings(*light, 16384);
  root->unref();
  return 0;
}
