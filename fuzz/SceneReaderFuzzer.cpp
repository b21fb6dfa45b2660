// libFuzzer harness: an .iv file as a user hands it to `ivshadow render`: read with the
// plugin's nodes registered (loadScene: the text checks, Coin's reader, the shape checks),
// then the casters' extraction that the group runs on its children.
#include "fuzz/FuzzInput.h"
#include "scene/InputError.h"
#include "scene/SceneTriangles.h"
#include "scene_input/SceneLoader.h"

#include <Inventor/nodes/SoSeparator.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ivshadow::fuzz::initOnce();
  const std::string path = ivshadow::fuzz::writeInput(data, size, ".iv");
  try {
    ivshadow::LoadedScene scene = ivshadow::loadScene(path);
    ivshadow::extractShadowCasters(scene.root.get());
  } catch (const ivshadow::InputError&) {
    // Refused with a message: what bad input should get.
  }
  return 0;
}
