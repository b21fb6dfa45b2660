#include "raytrace/SceneExtraction.h"

#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "raytrace/CameraFilter.h"
#include "raytrace/CasterScene.h"
#include "raytrace/CastingLight.h"
#include "raytrace/EmbreeHandles.h"
#include "scene/CoinRef.h"
#include "scene/DrawnColour.h"
#include "scene/EnvironmentValues.h"
#include "scene/LightLimit.h"
#include "scene/SceneTriangles.h"
#include "scene/ShadowTypes.h"
#include "scene/ShapeValidation.h"
#include "scene/Text3Sides.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/SbViewVolume.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/SoPrimitiveVertex.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/annex/FXViz/elements/SoShadowStyleElement.h>
#include <Inventor/annex/FXViz/nodes/SoShadowStyle.h>
#include <Inventor/elements/SoEnvironmentElement.h>
#include <Inventor/elements/SoLightElement.h>
#include <Inventor/elements/SoMultiTextureCoordinateElement.h>
#include <Inventor/elements/SoPolygonOffsetElement.h>
#include <Inventor/lists/SoNodeList.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoPointLight.h>
#include <Inventor/nodes/SoShape.h>
#include <Inventor/nodes/SoShapeHints.h>
#include <Inventor/nodes/SoSpotLight.h>
#include <Inventor/nodes/SoTextureCoordinateEnvironment.h>

#include <functional>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace ivshadow {
namespace {

using detail::cameraFilter;
using detail::Extraction;
using detail::Group;
using detail::Light;
using detail::LightType;
using detail::Material;
using detail::toGlm;
using detail::Triangle;

std::vector<int> currentLights(Extraction& data, SoState* state) {
  std::vector<int> result;
  const SoNodeList& lights = SoLightElement::getLights(state);
  for (int i = 0; i < lights.getLength(); ++i) {
    const auto found = data.lightOfNode.find(lights[i]);
    if (found != data.lightOfNode.end()) result.push_back(found->second);
  }
  return result;
}

int lightSetOf(Extraction& data, std::vector<int> lights) {
  std::sort(lights.begin(), lights.end());
  lights.erase(std::unique(lights.begin(), lights.end()), lights.end());
  const auto found = data.lightSetIndex.find(lights);
  if (found != data.lightSetIndex.end()) return found->second;
  const int index = int(data.lightSets.size());
  data.lightSets.push_back(lights);
  data.lightSetIndex.emplace(lights, index);
  return index;
}

SoCallbackAction::Response groupEnter(void* user, SoCallbackAction* action, const SoNode* node) {
  auto& data = *static_cast<Extraction*>(user);
  if (!static_cast<const SoTransparentShadowGroup*>(node)->isActive.getValue())
    return SoCallbackAction::CONTINUE;
  if (data.lightsOnly) {
    data.viewing = action->getViewingMatrix();
    const std::size_t index = data.groupsMet++;
    if (index >= data.groups.size() || data.groups[index].node != node) {
      data.groupsChanged = true;
      return SoCallbackAction::PRUNE;
    }
    Group& group = data.groups[index];
    group.lights.clear();
    group.casting.clear();
    data.groupStack.push_back(int(index));
    return SoCallbackAction::CONTINUE;
  }
  Group group;
  group.node = node;
  group.bounce = static_cast<const SoTransparentShadowGroup*>(node)->bounce.getValue() == TRUE;
  group.path = CoinRef<SoPath>(action->getCurPath()->copy());
  group.toWorld = action->getModelMatrix();
  data.groupStack.push_back(int(data.groups.size()));
  data.groups.push_back(std::move(group));
  return SoCallbackAction::CONTINUE;
}

// A SoPeelingSeparator shades its children with its own program, per pixel, as a group does.
SoCallbackAction::Response peelingEnter(void* user, SoCallbackAction*, const SoNode*) {
  ++static_cast<Extraction*>(user)->peelingDepth;
  return SoCallbackAction::CONTINUE;
}

SoCallbackAction::Response peelingLeave(void* user, SoCallbackAction*, const SoNode*) {
  --static_cast<Extraction*>(user)->peelingDepth;
  return SoCallbackAction::CONTINUE;
}

SoCallbackAction::Response groupLeave(void* user, SoCallbackAction*, const SoNode* node) {
  auto& data = *static_cast<Extraction*>(user);
  if (!data.groupStack.empty() && data.groups[std::size_t(data.groupStack.back())].node == node)
    data.groupStack.pop_back();
  return SoCallbackAction::CONTINUE;
}

SoCallbackAction::Response shadowStyle(void*, SoCallbackAction* action, const SoNode* node) {
  const auto* style = static_cast<const SoShadowStyle*>(node);
  SoShadowStyleElement::set(action->getState(), const_cast<SoNode*>(node), style->style.getValue());
  return SoCallbackAction::CONTINUE;
}

SoCallbackAction::Response cameraInGroup(void* user, SoCallbackAction* action, const SoNode*) {
  auto& data = *static_cast<Extraction*>(user);
  // Reading the lights alone (used only then), the camera the shapes of a group are viewed
  // with is the last one met in it, as a full read takes it from the triangles.
  if (!data.groupStack.empty()) data.viewing = action->getViewingMatrix();
  return SoCallbackAction::CONTINUE;
}

SoCallbackAction::Response light(void* user, SoCallbackAction* action, const SoNode* node) {
  auto& data = *static_cast<Extraction*>(user);
  const auto* base = static_cast<const SoLight*>(node);
  if (!base->on.getValue()) return SoCallbackAction::CONTINUE;
  // GL transforms a light by the modelview matrix in force where it is traversed: lights
  // before the camera are fixed in eye space (the headlight).
  const SbMatrix toEye = action->getModelMatrix() * action->getViewingMatrix();
  Light record;
  record.colour = toGlm(base->color.getValue()) * base->intensity.getValue();
  const SbVec3f attenuation = SoEnvironmentElement::getLightAttenuation(action->getState());
  record.attenuation = glm::vec3(attenuation[2], attenuation[1], attenuation[0]);
  if (node->isOfType(SoDirectionalLight::getClassTypeId())) {
    record.type = LightType::Directional;
    SbVec3f direction;
    toEye.multDirMatrix(-static_cast<const SoDirectionalLight*>(node)->direction.getValue(),
                        direction);
    record.eyeVector = toGlm(direction);
  } else if (node->isOfType(SoSpotLight::getClassTypeId())) {
    const auto* spot = static_cast<const SoSpotLight*>(node);
    record.type = LightType::Spot;
    SbVec3f position, direction;
    toEye.multVecMatrix(spot->location.getValue(), position);
    toEye.multDirMatrix(spot->direction.getValue(), direction);
    record.eyeVector = toGlm(position);
    record.eyeSpotDirection = toGlm(direction);
    // Coin's GL_SPOT_CUTOFF and GL_SPOT_EXPONENT.
    const float cutoff = std::min(glm::degrees(spot->cutOffAngle.getValue()), 90.0f);
    record.spotCosCutoff = std::cos(glm::radians(cutoff));
    record.spotExponent = spot->dropOffRate.getValue() * 128.0f;
  } else if (node->isOfType(SoPointLight::getClassTypeId())) {
    record.type = LightType::Point;
    SbVec3f position;
    toEye.multVecMatrix(static_cast<const SoPointLight*>(node)->location.getValue(), position);
    record.eyeVector = toGlm(position);
  } else {
    return SoCallbackAction::CONTINUE;
  }
  record.node = base;
  const int index = int(data.lights.size());
  data.lights.push_back(record);
  data.lightOfNode[node] = index;
  for (int group : data.groupStack) data.groups[std::size_t(group)].lights.push_back(index);
  return SoCallbackAction::CONTINUE;
}

void notTriangles(SoCallbackAction* action, Extraction& data) {
  // One path per instance (not per segment or point), for GL to draw each; each shape named
  // once.
  if (data.untracedShape == data.shape) return;
  data.untracedShape = data.shape;
  const SoPath* path = action->getCurPath();
  std::vector<int>& indices = data.untracedPaths.emplace_back(std::size_t(path->getLength()), 0);
  for (int i = 1; i < path->getLength(); ++i) indices[std::size_t(i)] = path->getIndex(i);
  const SoNode* node = action->getCurPathTail();
  if (data.skipped.count(node) != 0) return;
  data.skipped.emplace(node, describeNode(node));
  data.untracedShapes.push_back(describeNode(node));
}

SoCallbackAction::Response pruneShape(void*, SoCallbackAction*, const SoNode*) {
  return SoCallbackAction::PRUNE;
}

SoCallbackAction::Response shapeStart(void* user, SoCallbackAction* action, const SoNode* node) {
  auto& data = *static_cast<Extraction*>(user);
  ++data.shape;
  // What GL draws as pixels, outlines or points is said, not drawn.
  switch (shapeFill(action, node)) {
    case ShapeFill::Invisible:
      return SoCallbackAction::PRUNE;
    case ShapeFill::Unfilled:
      notTriangles(action, data);
      return SoCallbackAction::PRUNE;
    case ShapeFill::Filled:
      break;
  }
  return SoCallbackAction::CONTINUE;
}

SoCallbackAction::Response environmentFunction(void* user, SoCallbackAction*, const SoNode* node) {
  static_cast<Extraction*>(user)->environmentFunctions.push_back(node->getNodeId());
  return SoCallbackAction::CONTINUE;
}

// Which node set the texture coordinates of unit 0 and how: Coin keeps it in the element's
// unit data, which only a derived class may name. The element is Coin's, not this class: it is
// read through a pointer to the base's member, which the derived class forms, not through a
// cast of the element.
struct TextureCoordinateSource : SoMultiTextureCoordinateElement {
  static bool isEnvironment(SoState* state, const Extraction& data) {
    using UnitOf = const UnitData& (SoMultiTextureCoordinateElement::*)(int) const;
    const UnitOf unitOf = &TextureCoordinateSource::getUnitData;
    const UnitData& unit = (getInstance(state)->*unitOf)(0);
    return unit.whatKind == FUNCTION &&
           std::find(data.environmentFunctions.begin(), data.environmentFunctions.end(),
                     unit.nodeid) != data.environmentFunctions.end();
  }
};

// GL's sphere map (glTexGen GL_SPHERE_MAP, which Coin asks of GL for
// TextureCoordinateEnvironment) at a vertex of eye-space position `eye` and normal `normal`:
// the reflection of the direction from the eye about the unit normal. Coin's own software
// function, which SoCallbackAction hands over, reflects the normal instead, and its picture
// differs from what GL draws.
glm::vec2 sphereMap(const SbVec3f& eye, SbVec3f normal) {
  SbVec3f u = eye;
  u.normalize();
  normal.normalize();
  const SbVec3f r = u - 2.0f * normal.dot(u) * normal;
  const float m = 2.0f * std::sqrt(r[0] * r[0] + r[1] * r[1] + (r[2] + 1.0f) * (r[2] + 1.0f));
  if (!(m > 0.0f)) return glm::vec2(0.5f);
  return glm::vec2(r[0] / m + 0.5f, r[1] / m + 0.5f);
}

// A triangle's texture coordinates at its vertices, as GL takes them: the shape's, or GL's
// sphere map where a TextureCoordinateEnvironment generates them, through the texture matrix.
class TextureCoordinates {
 public:
  TextureCoordinates(SoCallbackAction* action, Extraction& data)
      : textureMatrix_(action->getTextureMatrix()),
        sphereMapped_(TextureCoordinateSource::isEnvironment(action->getState(), data)) {
    if (!sphereMapped_) return;
    data.texCoordsFollowView = true;
    modelView_ = action->getModelMatrix() * data.viewing;
    eyeNormals_ = modelView_.inverse().transpose();
  }

  glm::vec2 at(const SoPrimitiveVertex& v) const {
    SbVec4f generated = v.getTextureCoords();
    if (sphereMapped_) {
      SbVec3f eye, eyeNormal;
      modelView_.multVecMatrix(v.getPoint(), eye);
      eyeNormals_.multDirMatrix(v.getNormal(), eyeNormal);
      const glm::vec2 st = sphereMap(eye, eyeNormal);
      generated = SbVec4f(st.x, st.y, 0.0f, 1.0f);
    }
    SbVec4f tc;
    textureMatrix_.multVecMatrix(generated, tc);
    const float w = tc[3] != 0.0f ? tc[3] : 1.0f;
    return glm::vec2(tc[0] / w, tc[1] / w);
  }

 private:
  const SbMatrix& textureMatrix_;
  bool sphereMapped_;
  SbMatrix modelView_;
  SbMatrix eyeNormals_;
};

void triangle(void* user, SoCallbackAction* action, const SoPrimitiveVertex* v1,
              const SoPrimitiveVertex* v2, const SoPrimitiveVertex* v3) {
  auto& data = *static_cast<Extraction*>(user);
  SoState* state = action->getState();
  data.viewing = action->getViewingMatrix();
  data.projection = action->getProjectionMatrix();
  data.haveCamera = true;
  const SbMatrix& model = action->getModelMatrix();
  const SbMatrix normalMatrix = model.inverse().transpose();
  const TextureCoordinates texCoords(action, data);

  Triangle out;
  out.shape = data.shape;
  out.texture = currentTexture(action, data.textures, data.textureCache);
  out.lit = action->getLightModel() != SoLightModel::BASE_COLOR;
  // Coin turns two-sided lighting on for shapes of known vertex order that are not solid.
  out.clockwise = action->getVertexOrdering() == SoShapeHints::CLOCKWISE;
  out.twoSided = action->getVertexOrdering() != SoShapeHints::UNKNOWN_ORDERING &&
                 action->getShapeType() != SoShapeHints::SOLID;
  out.group = data.groupStack.empty() ? -1 : data.groupStack.back();
  out.perPixel = out.group >= 0 || data.peelingDepth > 0;
  out.shadowed =
      out.group >= 0 && (SoShadowStyleElement::get(state) & SoShadowStyleElement::SHADOWED) != 0;
  // The lights in force here, as GL lights the shape with them (a light in a separator of a
  // group lights what follows it there, not the whole group).
  out.lightSet = lightSetOf(data, currentLights(data, state));
  float factor = 0.0f, units = 0.0f;
  SoPolygonOffsetElement::Style styles = SoPolygonOffsetElement::FILLED;
  SbBool offset = FALSE;
  SoPolygonOffsetElement::get(state, factor, units, styles, offset);
  if (offset && (styles & SoPolygonOffsetElement::FILLED) != 0) {
    out.offsetFactor = factor;
    out.offsetUnits = units;
  }

  SbColor ambient, diffuse, specular, emission;
  float shininess = 0.0f, transparency = 0.0f;
  action->getMaterial(ambient, diffuse, specular, emission, shininess, transparency,
                      v1->getMaterialIndex());
  Material material;
  material.ambient = toGlm(ambient);
  material.specular = toGlm(specular);
  material.emission = toGlm(emission);
  material.shininess = shininess * 128.0f;
  const EnvironmentValues environment = EnvironmentValues::of(state);
  const float ambientIntensity = environment.ambientIntensity;
  const float fogVisibility = environment.fogVisibility, fogStart = environment.fogStart;
  const SbColor& ambientColour = environment.ambientColour;
  const SbColor& fogColour = environment.fogColour;
  const int32_t fogType = environment.fogType;
  material.globalAmbient = toGlm(ambientColour) * ambientIntensity;
  if (fogType != SoEnvironmentElement::NONE) {
    if (!(fogVisibility > 0.0f)) data.fogFollowsView = true;
    const SbViewVolume& volume = action->getViewVolume();
    const float far =
        fogVisibility > 0.0f ? fogVisibility : volume.getNearDist() + volume.getDepth();
    // Coin's density puts 1/256 of the colour through at the visibility distance.
    const float ln256 = std::log(256.0f);
    material.fogType = fogType == SoEnvironmentElement::HAZE  ? 1
                       : fogType == SoEnvironmentElement::FOG ? 2
                                                              : 3;
    material.fogColour = toGlm(fogColour);
    material.fogStart = fogStart;
    material.fogEnd = far;
    material.fogDensity = material.fogType == 2 ? ln256 / far : std::sqrt(ln256) / far;
  }
  // A shape's triangles come in a row and mostly share one material: keep it once.
  if (data.materials.empty() || !(data.materials.back() == material))
    data.materials.push_back(material);
  out.material = int(data.materials.size()) - 1;

  const SoPrimitiveVertex* vertices[3] = {v1, v2, v3};
  glm::vec3 world[3];
  for (int i = 0; i < 3; ++i) {
    const SoPrimitiveVertex* v = vertices[i];
    SbVec3f p, n;
    model.multVecMatrix(v->getPoint(), p);
    normalMatrix.multDirMatrix(v->getNormal(), n);
    world[i] = toGlm(p);
    out.normal[i] = toGlm(n);
    action->getMaterial(ambient, diffuse, specular, emission, shininess, transparency,
                        v->getMaterialIndex());
    out.colour[i] = drawnColour(diffuse, transparency);
    out.texCoord[i] = texCoords.at(*v);
    data.positions.push_back(world[i]);
  }
  out.geometricNormal = glm::cross(world[1] - world[0], world[2] - world[0]);
  const float alphas[3] = {out.colour[0].a, out.colour[1].a, out.colour[2].a};
  out.coverage = detail::coverageOf(alphas, out.texture >= 0);
  data.triangles.push_back(out);
}

void lineSegment(void* user, SoCallbackAction* action, const SoPrimitiveVertex*,
                 const SoPrimitiveVertex*) {
  notTriangles(action, *static_cast<Extraction*>(user));
}

void point(void* user, SoCallbackAction* action, const SoPrimitiveVertex*) {
  notTriangles(action, *static_cast<Extraction*>(user));
}

// Lights were recorded in eye space, as GL keeps them; shading happens in world space. Then
// the lights that cast in each group, decided as the group decides it
// (GroupContents::findLights).
void placeLights(Extraction& data) {
  // GL keeps a light where the model-view matrix put it when it was traversed, in eye space:
  // a camera met after it (a headlight's, or one inside a group) views it from there.
  const SbMatrix eyeToWorld = data.viewing.inverse();
  for (Light& light : data.lights) {
    SbVec3f v;
    if (light.type == LightType::Directional) {
      eyeToWorld.multDirMatrix(SbVec3f(light.eyeVector.x, light.eyeVector.y, light.eyeVector.z), v);
      light.towardsLight = toGlm(v);
    } else {
      eyeToWorld.multVecMatrix(SbVec3f(light.eyeVector.x, light.eyeVector.y, light.eyeVector.z), v);
      light.position = toGlm(v);
      eyeToWorld.multDirMatrix(
          SbVec3f(light.eyeSpotDirection.x, light.eyeSpotDirection.y, light.eyeSpotDirection.z), v);
      light.spotDirection = toGlm(v);
    }
  }
  for (const std::vector<int>& set : data.lightSets)
    if (set.size() > std::size_t(kMaxGlLights))
      warnLightsPastGlLimit(data.lights[std::size_t(set[kMaxGlLights])].node, int(set.size()));
  for (Group& group : data.groups) {
    const auto& node = *static_cast<const SoTransparentShadowGroup*>(group.node);
    group.casting.clear();
    for (int index : group.lights) {
      CastingLight where;
      if (int(group.casting.size()) < kMaxGlLights &&
          castingLight(*data.lights[std::size_t(index)].node, node, SbMatrix::identity(), where))
        group.casting.push_back(index);
    }
  }
}

}  // namespace

// Reads the scene through `apply` (applying the callback action to a node or a path), then
// builds the groups' casters and the camera rays' scene.
std::unique_ptr<SceneTracer::Data> SceneTracer::extract(
    int width, int height, const std::function<void(SoCallbackAction&)>& apply) {
  auto result = std::make_unique<Data>();
  result->width = width;
  result->height = height;
  Extraction& data = result->extraction;
  {
    SoCallbackAction action{SbViewportRegion(short(width), short(height))};
    Text3Sides text3;
    text3.addTo(action);
    action.addPreCallback(SoTransparentShadowGroup::getClassTypeId(), groupEnter, &data);
    action.addPostCallback(SoTransparentShadowGroup::getClassTypeId(), groupLeave, &data);
    action.addPreCallback(SoPeelingSeparator::getClassTypeId(), peelingEnter, &data);
    action.addPostCallback(SoPeelingSeparator::getClassTypeId(), peelingLeave, &data);
    action.addPreCallback(SoShadowStyle::getClassTypeId(), shadowStyle, nullptr);
    action.addPreCallback(SoTextureCoordinateEnvironment::getClassTypeId(), environmentFunction,
                          &data);
    action.addPreCallback(SoLight::getClassTypeId(), light, &data);
    action.addPreCallback(SoShape::getClassTypeId(), skipDefectiveShape, nullptr);
    action.addPreCallback(SoShape::getClassTypeId(), shapeStart, &data);
    action.addTriangleCallback(SoShape::getClassTypeId(), triangle, &data);
    action.addLineSegmentCallback(SoShape::getClassTypeId(), lineSegment, &data);
    action.addPointCallback(SoShape::getClassTypeId(), point, &data);
    apply(action);
  }
  placeLights(data);

  std::string error;
  result->device = createEmbreeDevice(error);
  if (!result->device) throw std::runtime_error(error);
  for (Group& group : data.groups) {
    // In the group's coordinates, from the state in force at the group (as the GL path takes
    // them), then placed in the world.
    SceneTriangles casters = extractShadowCasters(group.path.get());
    for (TriangleVertex& vertex : casters.vertices) {
      SbVec3f p;
      group.toWorld.multVecMatrix(SbVec3f(vertex.position), p);
      for (int i = 0; i < 3; ++i) vertex.position[i] = p[i];
    }
    group.casters = CasterScene::build(result->device.get(), std::move(casters), error);
    if (!group.casters) throw std::runtime_error(error);
    group.path = CoinRef<SoPath>();
  }

  result->scene = buildTriangleScene(
      result->device.get(), data.triangles.size(),
      [&data](std::size_t i) { return &data.positions[i].x; }, cameraFilter, error);
  if (!result->scene) throw std::runtime_error(error);
  result->packetWidth = nativePacketWidth(result->device.get());
  return result;
}

bool SceneTracer::updateLights(const SoPath* path) {
  Extraction& data = data_->extraction;
  // Triangles index light sets of the lights read before: they stay right while the same
  // lights are read in the same order.
  std::vector<const SoLight*> before;
  for (const Light& light : data.lights) before.push_back(light.node);
  data.lights.clear();
  data.lightOfNode.clear();
  data.groupStack.clear();
  data.lightsOnly = true;
  data.groupsMet = 0;
  data.groupsChanged = false;
  {
    // The viewport of the read: a level of detail picks the same children.
    SoCallbackAction action{SbViewportRegion(short(data_->width), short(data_->height))};
    action.addPreCallback(SoTransparentShadowGroup::getClassTypeId(), groupEnter, &data);
    action.addPostCallback(SoTransparentShadowGroup::getClassTypeId(), groupLeave, &data);
    action.addPostCallback(SoCamera::getClassTypeId(), cameraInGroup, &data);
    action.addPreCallback(SoLight::getClassTypeId(), light, &data);
    action.addPreCallback(SoShape::getClassTypeId(), pruneShape, nullptr);
    action.apply(const_cast<SoPath*>(path));
  }
  data.lightsOnly = false;
  data.groupStack.clear();
  if (data.groupsChanged || data.groupsMet != data.groups.size()) return false;
  if (data.lights.size() != before.size()) return false;
  for (std::size_t i = 0; i < before.size(); ++i)
    if (data.lights[i].node != before[i]) return false;
  placeLights(data);
  return true;
}

// What the scene read holds.
bool SceneTracer::viewDependent() const {
  return data_->extraction.fogFollowsView || data_->extraction.texCoordsFollowView;
}
bool SceneTracer::haveCamera() const {
  return data_->extraction.haveCamera;
}
const SbMatrix& SceneTracer::viewing() const {
  return data_->extraction.viewing;
}
const SbMatrix& SceneTracer::projection() const {
  return data_->extraction.projection;
}
std::size_t SceneTracer::triangles() const {
  return data_->extraction.triangles.size();
}
SbBox3f SceneTracer::bounds() const {
  SbBox3f box;
  for (const glm::vec3& p : data_->extraction.positions) box.extendBy(SbVec3f(p.x, p.y, p.z));
  return box;
}
const std::vector<std::string>& SceneTracer::untracedShapes() const {
  return data_->extraction.untracedShapes;
}
const std::vector<std::vector<int>>& SceneTracer::untracedPaths() const {
  return data_->extraction.untracedPaths;
}

}  // namespace ivshadow
