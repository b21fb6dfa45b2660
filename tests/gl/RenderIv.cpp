// The GL half of ShadowScene.h: kept apart so that the unit tests, which share the scenes and
// pictures but render only with the CPU reference, build without the headless renderer.
#include "ivshadow/IvShadowInit.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoSeparator.h>

#include <stdexcept>

namespace ivshadow::test {

Image renderIv(const std::string& text, int size, SoNode** rootOut) {
  init();
  std::string error;
  auto renderer = CheckedRenderer::create(size, size, error);
  if (!renderer) throw std::runtime_error("no headless GL context: " + error);
  SoSeparator* root = readIv(text);
  renderer->render(root);
  Image image = renderer->read();
  if (rootOut != nullptr) {
    *rootOut = root;
  } else {
    root->unref();
  }
  return image;
}

}  // namespace ivshadow::test
