#include "scene/SceneTriangles.h"

#include "scene/ShapeValidation.h"
#include "scene/Text3Sides.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/SoPath.h>
#include <Inventor/SoPrimitiveVertex.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/annex/FXViz/elements/SoShadowStyleElement.h>
#include <Inventor/annex/FXViz/nodes/SoShadowStyle.h>
#include <Inventor/elements/SoTextureQualityElement.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoImage.h>
#include <Inventor/nodes/SoShape.h>
#include <Inventor/nodes/SoText2.h>
#include <Inventor/nodes/SoTexture2.h>

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <tuple>

namespace ivshadow {
namespace {

struct Collector {
  SceneTriangles result;
  std::set<const SoNode*> withoutTriangles;
  std::map<int, std::pair<std::vector<TriangleVertex>, std::vector<std::uint32_t>>> byTexture;
  TextureCache textures;
  std::uint32_t shape = 0;
  // From the coordinates of the traversal's root to those the casters are kept in: the
  // inverse of the model matrix at the group, when the traversal starts above it.
  SbMatrix toGroup = SbMatrix::identity();
};

}  // namespace

std::string describeNode(const SoNode* node) {
  std::string name = node->getTypeId().getName().getString();
  if (node->getName().getLength() > 0)
    name += std::string(" '") + node->getName().getString() + "'";
  return name;
}

bool isGrey(float r, float g, float b) {
  constexpr float kStep = 1.0f / 255.0f;
  return std::fabs(r - g) < kStep && std::fabs(g - b) < kStep;
}

int currentTexture(SoCallbackAction* action, std::vector<TextureImage>& textures,
                   TextureCache& cache) {
  SbVec2s size;
  int components = 0;
  const unsigned char* data = action->getTextureImage(size, components);
  if (data == nullptr || size[0] <= 0 || size[1] <= 0 || components < 1 || components > 4)
    return -1;
  const int model = static_cast<int>(action->getTextureModel());
  const float quality = SoTextureQualityElement::get(action->getState());
  const auto key = std::make_tuple(data, int(size[0]), int(size[1]), components, model, quality);
  const auto found = cache.index.find(key);
  if (found != cache.index.end()) return found->second;

  TextureImage image;
  image.width = size[0];
  image.height = size[1];
  image.model = model;
  image.blendColour = action->getTextureBlendColor();
  image.repeatS = action->getTextureWrapS() == SoTexture2::REPEAT;
  image.repeatT = action->getTextureWrapT() == SoTexture2::REPEAT;
  const std::size_t texels = std::size_t(image.width) * std::size_t(image.height);
  image.rgba.resize(texels * 4);
  for (std::size_t i = 0; i < texels; ++i) {
    const unsigned char* in = data + i * std::size_t(components);
    unsigned char* out = &image.rgba[i * 4];
    const bool luminance = components <= 2;
    out[0] = in[0];
    out[1] = luminance ? in[0] : in[1];
    out[2] = luminance ? in[0] : in[2];
    out[3] = components == 2 ? in[1] : components == 4 ? in[3] : 255;
    if (out[0] != out[1] || out[1] != out[2]) image.grey = false;
    if (out[3] != 255) image.opaque = false;
  }
  setTextureFiltering(image, quality);
  const int index = static_cast<int>(textures.size());
  textures.push_back(std::move(image));
  cache.index.emplace(key, index);
  return index;
}

namespace {

SoCallbackAction::Response enterGroup(void* data, SoCallbackAction* action, const SoNode*) {
  static_cast<Collector*>(data)->toGroup = action->getModelMatrix().inverse();
  return SoCallbackAction::CONTINUE;
}

SoCallbackAction::Response shadowStyle(void*, SoCallbackAction* action, const SoNode* node) {
  const auto* style = static_cast<const SoShadowStyle*>(node);
  SoShadowStyleElement::set(action->getState(), const_cast<SoNode*>(node), style->style.getValue());
  return SoCallbackAction::CONTINUE;
}

void triangle(void* data, SoCallbackAction* action, const SoPrimitiveVertex* v1,
              const SoPrimitiveVertex* v2, const SoPrimitiveVertex* v3) {
  if (!(SoShadowStyleElement::get(action->getState()) & SoShadowStyleElement::CASTS_SHADOW)) return;
  auto& collector = *static_cast<Collector*>(data);
  const SbMatrix model = action->getModelMatrix() * collector.toGroup;
  const int texture = currentTexture(action, collector.result.textures, collector.textures);
  const SbMatrix& textureMatrix = action->getTextureMatrix();
  auto& [out, shapes] = collector.byTexture[texture];
  shapes.push_back(collector.shape);
  SbBox3f corners;
  bool transparent = false;
  for (const SoPrimitiveVertex* v : {v1, v2, v3}) {
    TriangleVertex vertex{};
    SbVec3f p;
    model.multVecMatrix(v->getPoint(), p);
    collector.result.bounds.extendBy(p);
    corners.extendBy(p);
    SbColor ambient, diffuse, specular, emission;
    float shininess = 0.0f, transparency = 0.0f;
    action->getMaterial(ambient, diffuse, specular, emission, shininess, transparency,
                        v->getMaterialIndex());
    SbVec4f tc;
    textureMatrix.multVecMatrix(v->getTextureCoords(), tc);
    const float w = tc[3] != 0.0f ? tc[3] : 1.0f;
    for (int i = 0; i < 3; ++i) {
      vertex.position[i] = p[i];
      vertex.colour[i] = diffuse[i];
    }
    vertex.colour[3] = 1.0f - transparency;
    vertex.texCoord[0] = tc[0] / w;
    vertex.texCoord[1] = tc[1] / w;
    const TextureImage* image = texture >= 0 ? &collector.result.textures[texture] : nullptr;
    if (vertex.colour[3] < 1.0f || (image != nullptr && !image->opaque)) {
      transparent = true;
      collector.result.hasTransparent = true;
      if (!isGrey(diffuse[0], diffuse[1], diffuse[2]) || (image != nullptr && !image->grey))
        collector.result.hasColouredTransparent = true;
    }
    out.push_back(vertex);
  }
  if (transparent) collector.result.transparentBounds.extendBy(corners);
}

}  // namespace

ShapeFill shapeFill(SoCallbackAction* action, const SoNode* node) {
  // Coin draws screen-aligned text and images as pixels at a projected point.
  if (node->isOfType(SoText2::getClassTypeId()) || node->isOfType(SoImage::getClassTypeId()))
    return ShapeFill::Unfilled;
  switch (action->getDrawStyle()) {
    case SoDrawStyle::INVISIBLE:
      return ShapeFill::Invisible;
    case SoDrawStyle::LINES:
    case SoDrawStyle::POINTS:
      return ShapeFill::Unfilled;
    default:
      return ShapeFill::Filled;
  }
}

namespace {

void notTriangles(Collector& collector, SoCallbackAction* action) {
  if (!(SoShadowStyleElement::get(action->getState()) & SoShadowStyleElement::CASTS_SHADOW)) return;
  const SoNode* node = action->getCurPathTail();
  if (!collector.withoutTriangles.insert(node).second) return;
  collector.result.withoutTriangles.push_back(describeNode(node));
}

void lineSegment(void* data, SoCallbackAction* action, const SoPrimitiveVertex*,
                 const SoPrimitiveVertex*) {
  notTriangles(*static_cast<Collector*>(data), action);
}

void point(void* data, SoCallbackAction* action, const SoPrimitiveVertex*) {
  notTriangles(*static_cast<Collector*>(data), action);
}

// Before each shape: counts it, and prunes what Coin's GL rendering would not fill.
SoCallbackAction::Response startShape(void* data, SoCallbackAction* action, const SoNode* node) {
  auto& collector = *static_cast<Collector*>(data);
  // A shape left of the path to the group is outside it (Coin traverses only the nodes there
  // that affect the state, which shapes do not; this holds for node classes that forget to).
  if (action->getCurPathCode() == SoAction::OFF_PATH) return SoCallbackAction::PRUNE;
  ++collector.shape;
  if (skipDefectiveShape(nullptr, action, node) == SoCallbackAction::PRUNE)
    return SoCallbackAction::PRUNE;
  // What GL does not fill casts nothing; what it draws as pixels, outlines or points is said.
  switch (shapeFill(action, node)) {
    case ShapeFill::Invisible:
      return SoCallbackAction::PRUNE;
    case ShapeFill::Unfilled:
      notTriangles(collector, action);
      return SoCallbackAction::PRUNE;
    case ShapeFill::Filled:
      break;
  }
  return SoCallbackAction::CONTINUE;
}

SceneTriangles extract(const std::function<void(SoCallbackAction&)>& apply) {
  Collector collector;
  SoCallbackAction action;
  Text3Sides text3;
  text3.addTo(action);
  action.addPreCallback(SoShape::getClassTypeId(), startShape, &collector);
  // Called only when the action is applied to a path: at the group, its tail.
  action.addPreTailCallback(enterGroup, &collector);
  action.addPreCallback(SoShadowStyle::getClassTypeId(), shadowStyle, nullptr);
  action.addTriangleCallback(SoShape::getClassTypeId(), triangle, &collector);
  action.addLineSegmentCallback(SoShape::getClassTypeId(), lineSegment, &collector);
  action.addPointCallback(SoShape::getClassTypeId(), point, &collector);
  apply(action);

  SceneTriangles& result = collector.result;
  for (auto& [texture, triangles] : collector.byTexture) {
    const auto& [vertices, shapes] = triangles;
    TriangleBatch batch;
    batch.texture = texture;
    batch.firstVertex = result.vertices.size();
    batch.vertexCount = vertices.size();
    result.vertices.insert(result.vertices.end(), vertices.begin(), vertices.end());
    result.shapes.insert(result.shapes.end(), shapes.begin(), shapes.end());
    result.batches.push_back(batch);
  }
  return std::move(result);
}

}  // namespace

SceneTriangles extractShadowCasters(SoNode* root) {
  return extract([root](SoCallbackAction& action) { action.apply(root); });
}

SceneTriangles extractShadowCasters(const SoPath* toGroup) {
  return extract(
      [toGroup](SoCallbackAction& action) { action.apply(const_cast<SoPath*>(toGroup)); });
}

}  // namespace ivshadow
