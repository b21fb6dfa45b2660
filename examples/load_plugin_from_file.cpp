// An Inventor program that does not link the plugin: it links Coin and libepoxy (GL and EGL
// entry points) only.
// Reading a scene that uses TransparentShadowGroup / DeepShadowLight / PeelingSeparator makes
// Coin load the plugin by those names from the library path (LD_LIBRARY_PATH=<plugin dir>),
// and the scene renders with its transparent, coloured shadows. It draws headlessly into a
// framebuffer object of a surfaceless EGL context and writes a binary PPM.
// Usage: LD_LIBRARY_PATH=build/lib load_plugin_from_file SCENE.iv OUT.ppm [WIDTHxHEIGHT]
#include "ExampleGl.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/misc/SoContextHandler.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cstdio>
#include <fstream>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: load_plugin_from_file SCENE.iv OUT.ppm [WIDTHxHEIGHT]\n");
    return 2;
  }
  int width = 640, height = 480;
  if (argc > 3 && std::sscanf(argv[3], "%dx%d", &width, &height) != 2) return 2;

  SoDB::init();  // nothing else: the plugin comes in through the scene file
  SoInput input;
  if (!input.openFile(argv[1])) return 2;
  SoSeparator* root = SoDB::readAll(&input);
  if (root == nullptr) return 2;
  root->ref();

  if (!example::makeContext()) {
    std::fprintf(stderr, "load_plugin_from_file: no EGL context\n");
    return 3;
  }
  example::bindFramebuffer(width, height);
  const std::uint32_t cacheContext = example::render(root, width, height);

  std::vector<unsigned char> pixels(std::size_t(width) * std::size_t(height) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  std::ofstream out(argv[2], std::ios::binary);
  out << "P6\n" << width << ' ' << height << "\n255\n";
  for (int y = height - 1; y >= 0; --y)  // GL rows are bottom-up, PPM rows top-down
    out.write(reinterpret_cast<const char*>(&pixels[std::size_t(y) * std::size_t(width) * 3]),
              std::streamsize(width) * 3);

  // Let the plugin free its GL resources while the context is still current.
  SoContextHandler::destructingContext(cacheContext);
  root->unref();
  std::printf("wrote %s\n", argv[2]);
  return out ? 0 : 1;
}
