// Builds a scene graph in C++ with the plugin's nodes — a red and a green glass slab over a
// white floor, in a SoTransparentShadowGroup lit by a SoDeepShadowLight, the glasses inside a
// SoPeelingSeparator — and renders it headlessly to a PNG. It uses the installed headers only;
// the GL context is its own (ExampleGl.h), the PNG is written with libpng.
// Usage: render_scene_graph OUT.png
#include <ivshadow/DeepShadowStatistics.h>
#include <ivshadow/IvShadowInit.h>
#include <ivshadow/SoDeepShadowLight.h>
#include <ivshadow/SoPeelingSeparator.h>
#include <ivshadow/SoTransparentShadowGroup.h>

#include "ExampleGl.h"

#include <png.h>

#include <Inventor/misc/SoContextHandler.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>
#include <Inventor/nodes/SoTranslation.h>

#include <iostream>
#include <vector>

namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 480;

// Reads the framebuffer and writes it as an 8-bit RGB PNG.
bool writeFramebufferPng(const char* path) {
  std::vector<unsigned char> pixels(std::size_t(kWidth) * std::size_t(kHeight) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = kWidth;
  image.height = kHeight;
  image.format = PNG_FORMAT_RGB;
  // A negative row stride: GL rows are bottom-up, PNG rows top-down.
  return png_image_write_to_file(&image, path, 0, pixels.data(), -kWidth * 3, nullptr) != 0;
}

// A square slab `size` wide and `thickness` high centred at `centre`, in its own separator.
void addSlab(SoGroup* scene, const SbVec3f& centre, float size, float thickness,
             const SbColor& colour, float transparency) {
  auto* slab = new SoSeparator;
  auto* place = new SoTranslation;
  place->translation.setValue(centre);
  auto* material = new SoMaterial;
  material->diffuseColor.setValue(colour);
  material->transparency = transparency;
  auto* box = new SoCube;
  box->width = size;
  box->height = thickness;
  box->depth = size;
  slab->addChild(place);
  slab->addChild(material);
  slab->addChild(box);
  scene->addChild(slab);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: render_scene_graph OUT.png\n";
    return 2;
  }
  ivshadow::init();

  auto* scene = new SoSeparator;
  scene->ref();
  auto* hints = new SoShapeHints;
  hints->vertexOrdering = SoShapeHints::COUNTERCLOCKWISE;
  hints->shapeType = SoShapeHints::SOLID;
  scene->addChild(hints);
  auto* camera = new SoPerspectiveCamera;
  camera->position.setValue(0.0f, 4.0f, 6.0f);
  camera->pointAt(SbVec3f(0.0f, 0.0f, 0.0f));
  scene->addChild(camera);
  // Everything under the group receives shadows; the light's map is built by the group.
  auto* group = new SoTransparentShadowGroup;
  scene->addChild(group);
  auto* light = new SoDeepShadowLight;
  light->location.setValue(0.0f, 3.0f, 0.0f);
  light->colorModel = SoDeepShadowLight::SATURATE;
  group->addChild(light);
  addSlab(group, SbVec3f(0.0f, 0.0f, 0.0f), 6.0f, 0.1f, SbColor(1.0f, 1.0f, 1.0f), 0.0f);
  // The glasses overlap from the camera: peeling composites them in depth order.
  auto* glasses = new SoPeelingSeparator;
  group->addChild(glasses);
  addSlab(glasses, SbVec3f(-0.3f, 1.0f, 0.0f), 1.5f, 0.05f, SbColor(1.0f, 0.0f, 0.0f), 0.5f);
  addSlab(glasses, SbVec3f(0.4f, 1.6f, 0.3f), 1.2f, 0.05f, SbColor(0.0f, 1.0f, 0.0f), 0.5f);

  if (!example::makeContext()) {
    std::cerr << "render_scene_graph: error: no EGL context\n";
    scene->unref();
    return 3;
  }
  example::bindFramebuffer(kWidth, kHeight);
  const std::uint32_t cacheContext = example::render(scene, kWidth, kHeight);
  if (!writeFramebufferPng(argv[1])) {
    std::cerr << "render_scene_graph: error: cannot write " << argv[1] << '\n';
    scene->unref();
    return 1;
  }
  // Statistics of the frame: on a GPU the map was built once and the glasses peeled; on a
  // software rasteriser the group's renderer (AUTO) traced the frame on the CPU instead.
  const ivshadow::DeepShadowStatistics stats = ivshadow::collectDeepShadowStatistics(scene);
  // Let the plugin free its GL resources while the context is still current.
  SoContextHandler::destructingContext(cacheContext);
  scene->unref();
  std::cout << "wrote " << argv[1];
  if (stats.tracerFrames > 0)
    std::cout << " (traced on the CPU: " << stats.tracerFrames << " frame, "
              << stats.tracerCameraRays << " camera rays)\n";
  else
    std::cout << " (deep shadow map built " << stats.rebuilds << " time, " << stats.lights.size()
              << " light)\n";
  return 0;
}
