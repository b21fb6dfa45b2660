// Builds a scene graph in C++ with the plugin's nodes — a red and a green glass slab over a
// white floor, in a SoTransparentShadowGroup lit by a SoDeepShadowLight, the glasses inside a
// SoPeelingSeparator — and renders it headlessly to a PNG with the plugin's renderer.
// Usage: render_scene_graph OUT.png
#include "headless/OffscreenRenderer.h"
#include "image/PngFile.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>
#include <Inventor/nodes/SoTranslation.h>

#include <iostream>

namespace {

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

  std::string error;
  auto renderer = ivshadow::OffscreenRenderer::create(640, 480, error);
  if (!renderer) {
    std::cerr << "render_scene_graph: error: " << error << '\n';
    scene->unref();
    return 3;
  }
  // ViewSetup adds a camera or headlight only where a scene lacks them; this one has both.
  const ivshadow::ViewSetup view = ivshadow::ViewSetup::prepare(scene, SbViewportRegion(640, 480));
  renderer->render(view.root.get());
  ivshadow::writePng(argv[1], renderer->read());
  // Statistics of the frame: the map was built once, the glasses peeled.
  const ivshadow::DeepShadowStatistics stats = ivshadow::collectDeepShadowStatistics(scene);
  scene->unref();
  std::cout << "wrote " << argv[1] << " (deep shadow map built " << stats.rebuilds << " time, "
            << stats.lights.size() << " light)\n";
  return 0;
}
