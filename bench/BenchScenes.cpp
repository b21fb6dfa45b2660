#include "BenchScenes.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/annex/FXViz/nodes/SoShadowGroup.h>
#include <Inventor/annex/FXViz/nodes/SoShadowSpotLight.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoNormal.h>
#include <Inventor/nodes/SoNormalBinding.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoPointLight.h>
#include <Inventor/nodes/SoQuadMesh.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>
#include <Inventor/nodes/SoTranslation.h>

#include <cmath>
#include <vector>

namespace ivshadow::bench {
namespace {

// A unit lat-long sphere of n x n quads (2 n^2 triangles) with per-vertex normals.
SoSeparator* sphereMesh(int n) {
  auto* sphere = new SoSeparator;
  auto* coords = new SoCoordinate3;
  auto* normals = new SoNormal;
  std::vector<SbVec3f> points;
  const double pi = std::acos(-1.0);
  for (int row = 0; row <= n; ++row) {
    const double theta = pi * row / n;
    for (int column = 0; column <= n; ++column) {
      const double phi = 2.0 * pi * column / n;
      points.emplace_back(float(std::sin(theta) * std::cos(phi)),
                          float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
    }
  }
  normals->vector.setValues(0, int(points.size()), points.data());
  for (SbVec3f& p : points) p *= 0.6f;
  coords->point.setValues(0, int(points.size()), points.data());
  auto* binding = new SoNormalBinding;
  binding->value = SoNormalBinding::PER_VERTEX_INDEXED;
  auto* mesh = new SoQuadMesh;
  mesh->verticesPerRow = n + 1;
  mesh->verticesPerColumn = n + 1;
  sphere->addChild(coords);
  sphere->addChild(normals);
  sphere->addChild(binding);
  sphere->addChild(mesh);
  return sphere;
}

}  // namespace

SoSeparator* sphereField(int triangles, bool transparent, Shadows shadows, int width, int height) {
  // Few spheres for small counts, a 10 x 10 field for large ones.
  const int side = triangles >= 100000 ? 10 : triangles >= 10000 ? 4 : 1;
  const int spheres = side * side;
  const int n = std::max(4, int(std::lround(std::sqrt(triangles / (2.0 * spheres)))));

  auto* root = new SoSeparator;
  root->ref();
  auto* camera = new SoPerspectiveCamera;
  camera->position.setValue(0.0f, -9.0f, 8.0f);
  camera->orientation.setValue(SbVec3f(1, 0, 0), 0.8f);
  camera->nearDistance = 1.0f;
  camera->farDistance = 40.0f;
  root->addChild(camera);
  auto* hints = new SoShapeHints;
  hints->vertexOrdering = SoShapeHints::COUNTERCLOCKWISE;
  hints->shapeType = SoShapeHints::UNKNOWN_SHAPE_TYPE;
  root->addChild(hints);

  SoSeparator* group = nullptr;
  switch (shadows) {
    case Shadows::None:
      group = new SoSeparator;
      break;
    case Shadows::DeepShadowGroup:
      group = new SoTransparentShadowGroup;
      break;
    case Shadows::CoinShadowGroup:
      group = new SoShadowGroup;
      break;
  }
  root->addChild(group);
  const SbVec3f lightAt(0.5f, -0.5f, 6.0f);
  if (shadows == Shadows::CoinShadowGroup) {
    auto* spot = new SoShadowSpotLight;
    spot->location = lightAt;
    spot->direction.setValue(0.0f, 0.0f, -1.0f);
    spot->cutOffAngle = 1.2f;
    spot->dropOffRate = 0.0f;
    group->addChild(spot);
  } else if (shadows == Shadows::DeepShadowGroup) {
    auto* light = new SoDeepShadowLight;
    light->location = lightAt;
    light->setName("Lamp");
    group->addChild(light);
  } else {
    auto* light = new SoPointLight;
    light->location = lightAt;
    group->addChild(light);
  }

  auto* floor = new SoSeparator;
  auto* floorCoords = new SoCoordinate3;
  const SbVec3f corners[4] = {{-8, -8, 0}, {8, -8, 0}, {8, 8, 0}, {-8, 8, 0}};
  floorCoords->point.setValues(0, 4, corners);
  floor->addChild(floorCoords);
  floor->addChild(new SoFaceSet);
  group->addChild(floor);

  SoSeparator* mesh = sphereMesh(n);
  const float spacing = 1.4f;
  for (int i = 0; i < spheres; ++i) {
    auto* placed = new SoSeparator;
    auto* at = new SoTranslation;
    at->translation.setValue((float(i % side) - 0.5f * float(side - 1)) * spacing,
                             (float(i / side) - 0.5f * float(side - 1)) * spacing, 2.0f);
    auto* material = new SoMaterial;
    const bool glass = transparent && i % 2 == 0;
    material->diffuseColor.setValue(glass ? SbColor(0.2f + 0.6f * float(i % 3 == 0), 0.8f, 0.3f)
                                          : SbColor(0.7f, 0.7f, 0.7f));
    material->transparency = glass ? 0.5f : 0.0f;
    placed->addChild(at);
    placed->addChild(material);
    placed->addChild(mesh);
    group->addChild(placed);
  }
  camera->viewAll(root, SbViewportRegion(short(width), short(height)));
  return root;
}

}  // namespace ivshadow::bench
