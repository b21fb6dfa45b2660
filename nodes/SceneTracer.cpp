#include "nodes/SceneTracer.h"

#include "callbacks/ShaderConstants.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/CastingLight.h"
#include "nodes/DeepShadowSettings.h"
#include "raytrace/CasterScene.h"
#include "raytrace/EmbreeHandles.h"
#include "raytrace/ParallelRows.h"
#include "raytrace/SurfaceOptics.h"
#include "scene/CoinRef.h"
#include "scene/EnvironmentValues.h"
#include "scene/SceneTriangles.h"
#include "scene/ShapeValidation.h"

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
#include <Inventor/lists/SoNodeList.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoPointLight.h>
#include <Inventor/nodes/SoShape.h>
#include <Inventor/nodes/SoShapeHints.h>
#include <Inventor/nodes/SoSpotLight.h>

#include <cstring>
#include <functional>
#include <limits>

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace ivshadow {
namespace {

glm::vec3 toGlm(const SbVec3f& v) {
  return glm::vec3(v[0], v[1], v[2]);
}

enum class LightType { Directional, Point, Spot };

struct Light {
  LightType type = LightType::Point;
  glm::vec3 colour{1.0f};     // colour × intensity (Coin's GL diffuse and specular)
  glm::vec3 eyeVector{0.0f};  // eye space: position, or direction towards the light
  glm::vec3 eyeSpotDirection{0.0f, 0.0f, -1.0f};
  glm::vec3 position{0.0f};  // world space (filled once the camera is known)
  glm::vec3 towardsLight{0.0f};
  glm::vec3 spotDirection{0.0f};
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};  // constant, linear, quadratic
  float spotCosCutoff = -1.0f;
  float spotExponent = 0.0f;
  const SoLight* node = nullptr;
};

struct Group {
  SbMatrix toWorld;
  const SoNode* node = nullptr;
  CoinRef<SoPath> path;  // from the root: its casters are taken in the state in force there
  std::vector<int> outsideLights;  // lit the group from outside (SoLightElement at entry)
  std::vector<int> lights;         // every light turned on in the group's subgraph
  std::vector<int> casting;        // those that cast (nodes/CastingLight.h), as many as GL's
  std::unique_ptr<CasterScene> casters;
  bool bounce = false;  // its bounce field
};

struct Material {
  glm::vec3 ambient{0.2f};
  glm::vec3 specular{0.0f};
  glm::vec3 emission{0.0f};
  float shininess = 0.0f;  // GL exponent (Coin's 0..1 × 128)
  glm::vec3 globalAmbient{0.2f};
  // Coin's GL fog (SoGLEnvironmentElement): 0 none, 1 linear (HAZE), 2 exp (FOG),
  // 3 exp2 (SMOKE), with the distances and density it derives from the visibility.
  int fogType = 0;
  glm::vec3 fogColour{0.0f};
  float fogStart = 0.0f;
  float fogEnd = 1.0f;
  float fogDensity = 0.0f;

  bool operator==(const Material& o) const {
    return ambient == o.ambient && specular == o.specular && emission == o.emission &&
           shininess == o.shininess && globalAmbient == o.globalAmbient && fogType == o.fogType &&
           fogColour == o.fogColour && fogStart == o.fogStart && fogEnd == o.fogEnd &&
           fogDensity == o.fogDensity;
  }
};

struct Triangle {
  glm::vec3 normal[3];
  glm::vec4 colour[3];
  glm::vec2 texCoord[3];
  glm::vec3 geometricNormal;  // from the winding: counter-clockwise front
  int material = 0;
  int texture = -1;
  int lightSet = -1;  // outside groups
  int group = -1;     // innermost active SoTransparentShadowGroup
  bool lit = true;
  bool twoSided = false;
  bool clockwise = false;
  bool shadowed = false;
  std::uint32_t shape = 0;
};

struct Extraction {
  std::vector<glm::vec3> positions;  // three per triangle, world space
  std::vector<Triangle> triangles;
  std::vector<Material> materials;
  std::vector<TextureImage> textures;
  TextureCache textureCache;
  std::vector<Light> lights;
  std::map<const SoNode*, int> lightOfNode;  // the latest record of each light node
  std::vector<std::vector<int>> lightSets;
  std::map<std::vector<int>, int> lightSetIndex;
  std::vector<Group> groups;
  std::vector<int> groupStack;
  std::map<const SoNode*, std::string> skipped;  // shapes without triangles
  std::vector<std::string> untracedShapes;       // their names, in traversal order
  std::vector<CoinRef<SoPath>> untracedPaths;    // and the paths to every instance
  std::uint32_t untracedShape = ~0u;             // the instance (shape) a path was kept for
  SbMatrix viewing = SbMatrix::identity();
  SbMatrix projection = SbMatrix::identity();
  bool haveCamera = false;
  std::uint32_t shape = 0;
  // Some fog's distance is the view volume's depth (visibility 0): a moved camera changes it.
  bool fogFollowsView = false;
  // A pass that reads only the lights again (SceneTracer::updateLights): the groups met are
  // the ones read before, in the same order.
  bool lightsOnly = false;
  std::size_t groupsMet = 0;
  bool groupsChanged = false;  // ... and they were not
};

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
    group.outsideLights = currentLights(data, action->getState());
    data.groupStack.push_back(int(index));
    return SoCallbackAction::CONTINUE;
  }
  Group group;
  group.node = node;
  group.bounce = static_cast<const SoTransparentShadowGroup*>(node)->bounce.getValue() == TRUE;
  group.path = CoinRef<SoPath>(action->getCurPath()->copy());
  group.toWorld = action->getModelMatrix();
  group.outsideLights = currentLights(data, action->getState());
  data.groupStack.push_back(int(data.groups.size()));
  data.groups.push_back(std::move(group));
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
  data.untracedPaths.emplace_back(action->getCurPath()->copy());
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

void triangle(void* user, SoCallbackAction* action, const SoPrimitiveVertex* v1,
              const SoPrimitiveVertex* v2, const SoPrimitiveVertex* v3) {
  auto& data = *static_cast<Extraction*>(user);
  SoState* state = action->getState();
  data.viewing = action->getViewingMatrix();
  data.projection = action->getProjectionMatrix();
  data.haveCamera = true;
  const SbMatrix& model = action->getModelMatrix();
  const SbMatrix normalMatrix = model.inverse().transpose();
  const SbMatrix& textureMatrix = action->getTextureMatrix();

  Triangle out;
  out.shape = data.shape;
  out.texture = currentTexture(action, data.textures, data.textureCache);
  out.lit = action->getLightModel() != SoLightModel::BASE_COLOR;
  // Coin turns two-sided lighting on for shapes of known vertex order that are not solid.
  out.clockwise = action->getVertexOrdering() == SoShapeHints::CLOCKWISE;
  out.twoSided = action->getVertexOrdering() != SoShapeHints::UNKNOWN_ORDERING &&
                 action->getShapeType() != SoShapeHints::SOLID;
  out.group = data.groupStack.empty() ? -1 : data.groupStack.back();
  out.shadowed =
      out.group >= 0 && (SoShadowStyleElement::get(state) & SoShadowStyleElement::SHADOWED) != 0;
  if (out.group < 0) out.lightSet = lightSetOf(data, currentLights(data, state));

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
    out.colour[i] = glm::vec4(toGlm(diffuse), 1.0f - transparency);
    SbVec4f tc;
    textureMatrix.multVecMatrix(v->getTextureCoords(), tc);
    const float w = tc[3] != 0.0f ? tc[3] : 1.0f;
    out.texCoord[i] = glm::vec2(tc[0] / w, tc[1] / w);
    data.positions.push_back(world[i]);
  }
  out.geometricNormal = glm::cross(world[1] - world[0], world[2] - world[0]);
  data.triangles.push_back(out);
}

void lineSegment(void* user, SoCallbackAction* action, const SoPrimitiveVertex*,
                 const SoPrimitiveVertex*) {
  notTriangles(action, *static_cast<Extraction*>(user));
}

void point(void* user, SoCallbackAction* action, const SoPrimitiveVertex*) {
  notTriangles(action, *static_cast<Extraction*>(user));
}

using Hit = SurfacesMet::Hit;

// Every surface a camera ray meets, collected by Embree's filter function.
struct CameraRayContext : RTCIntersectContext {
  const Extraction* data = nullptr;
  std::vector<Hit>* hits = nullptr;
};

const TextureImage* imageOf(const Extraction& data, const Triangle& tri) {
  return tri.texture >= 0 ? &data.textures[std::size_t(tri.texture)] : nullptr;
}

float opacity(const Extraction& data, const Triangle& tri, float u, float v) {
  const TextureImage* image = imageOf(data, tri);
  const SurfaceSample sample = sampleSurface(tri.colour, tri.texCoord, image, u, v);
  return texturedColour(sample.colour, sample.texel, image).a;
}

void cameraFilter(const RTCFilterFunctionNArguments* args) {
  auto& context = *static_cast<CameraRayContext*>(args->context);
  Hit hit;
  hit.primitive = RTCHitN_primID(args->hit, args->N, 0);
  hit.u = RTCHitN_u(args->hit, args->N, 0);
  hit.v = RTCHitN_v(args->hit, args->N, 0);
  hit.t = RTCRayN_tfar(args->ray, args->N, 0);
  const float alpha = opacity(*context.data, context.data->triangles[hit.primitive], hit.u, hit.v);
  // An opaque surface is accepted: Embree then only looks for nearer ones. The others are
  // collected and passed over.
  if (isOpaque(alpha)) return;
  if (alpha > 0.0f) context.hits->push_back(hit);
  args->valid[0] = 0;
}

struct RayCounts {
  std::size_t shadow = 0;
  std::size_t bounce = 0;
};

// One pixel's composite (TracedPixels): premultiplied colour, transmittance, window depth.
struct PixelResult {
  glm::vec3 colour{0.0f};
  float transmitted = 1.0f;
  float depth = 1.0f;
};

class Tracer {
 public:
  Tracer(const Extraction& data, RTCScene scene, const SbMatrix& viewing,
         const SbMatrix& projection, const TraceOptions& options)
      : data_(data), scene_(scene), options_(options), viewing_(viewing) {
    worldToClip_ = viewing * projection;
    clipToWorld_ = worldToClip_.inverse();
    SbVec3f back;
    viewing.inverse().multDirMatrix(SbVec3f(0.0f, 0.0f, 1.0f), back);
    back.normalize();
    viewDirection_ = toGlm(back);
  }

  // A pixel's ray: from the near plane (t = 0) to the far plane (t = 1).
  struct CameraRay {
    float nx, ny;  // the pixel's centre in normalised device coordinates
    glm::vec3 origin;
    glm::vec3 direction;
  };
  CameraRay cameraRay(int x, int y) const {
    CameraRay ray;
    ray.nx = (float(x) + 0.5f) / float(options_.width) * 2.0f - 1.0f;
    ray.ny = 1.0f - (float(y) + 0.5f) / float(options_.height) * 2.0f;
    SbVec3f nearPoint, farPoint;
    clipToWorld_.multVecMatrix(SbVec3f(ray.nx, ray.ny, -1.0f), nearPoint);
    clipToWorld_.multVecMatrix(SbVec3f(ray.nx, ray.ny, 1.0f), farPoint);
    ray.origin = toGlm(nearPoint);
    ray.direction = toGlm(farPoint) - ray.origin;
    return ray;
  }

  // The surfaces along `ray` into `hits` (surfacesAlong), ending at `limit`, the window depth
  // where the ray ends (1: the far plane). Returns the window depth of the nearest opaque
  // one, or `limit` where there is none.
  float visible(const CameraRay& ray, float limit, std::vector<Hit>& hits) const {
    float tfar = 1.0f;  // the far plane clips as in GL
    if (limit < 1.0f) {
      // The limit's point on this ray: its parameter, as the ray is linear in the world.
      SbVec3f end;
      clipToWorld_.multVecMatrix(SbVec3f(ray.nx, ray.ny, 2.0f * limit - 1.0f), end);
      tfar =
          glm::dot(toGlm(end) - ray.origin, ray.direction) / glm::dot(ray.direction, ray.direction);
    }
    if (!surfacesAlong(ray.origin, ray.direction, 0.0f, tfar, hits)) return limit;
    SbVec3f clip;
    const glm::vec3 p = ray.origin + hits.back().t * ray.direction;
    worldToClip_.multVecMatrix(SbVec3f(p.x, p.y, p.z), clip);
    return glm::clamp(0.5f * clip[2] + 0.5f, 0.0f, 1.0f);
  }

  // The `count` surfaces `hits` met along `ray`, shaded and composited front to back.
  PixelResult composite(const CameraRay& ray, const Hit* hits, std::size_t count, float depth,
                        RayCounts& rays) const {
    PixelResult result;
    result.depth = depth;
    for (std::size_t i = 0; i < count; ++i) {
      const Hit& hit = hits[i];
      const Triangle& tri = data_.triangles[hit.primitive];
      if (metBefore(hits, i)) continue;
      const glm::vec3 position = ray.origin + hit.t * ray.direction;
      const glm::vec4 shaded = shade(tri, hit, position, ray.direction, rays);
      const float alpha = isOpaque(shaded.a) ? 1.0f : glm::clamp(shaded.a, 0.0f, 1.0f);
      result.colour += result.transmitted * alpha * glm::vec3(shaded);
      result.transmitted *= 1.0f - alpha;
      if (result.transmitted <= 0.0f) break;
    }
    result.transmitted = std::max(result.transmitted, 0.0f);
    return result;
  }

 private:
  // Every surface along origin + t direction, tnear < t < tfar, into `hits` in exact depth
  // order (coincident ones in the order Coin traversed them), ending at the first opaque one
  // if there is one; true when there is.
  bool surfacesAlong(const glm::vec3& origin, const glm::vec3& direction, float tnear, float tfar,
                     std::vector<Hit>& hits) const {
    hits.clear();
    CameraRayContext context;
    rtcInitIntersectContext(&context);
    context.data = &data_;
    context.hits = &hits;
    RTCRayHit rayHit{};
    rayHit.ray.org_x = origin.x;
    rayHit.ray.org_y = origin.y;
    rayHit.ray.org_z = origin.z;
    rayHit.ray.dir_x = direction.x;
    rayHit.ray.dir_y = direction.y;
    rayHit.ray.dir_z = direction.z;
    rayHit.ray.tnear = tnear;
    rayHit.ray.tfar = tfar;
    rayHit.ray.mask = 0xFFFFFFFFu;
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rayHit);
    const bool opaqueHit = rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    const float limit = rayHit.ray.tfar;
    hits.erase(std::remove_if(hits.begin(), hits.end(),
                              [&](const Hit& h) { return opaqueHit && h.t >= limit; }),
               hits.end());
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
      return a.t != b.t ? a.t < b.t : a.primitive < b.primitive;
    });
    if (opaqueHit) hits.push_back(Hit{limit, rayHit.hit.primID, rayHit.hit.u, rayHit.hit.v});
    return opaqueHit;
  }

  // Whether hits[i] is a surface met before (a shared edge, a spatial split): composited once.
  bool metBefore(const Hit* hits, std::size_t i) const {
    const Triangle& tri = data_.triangles[hits[i].primitive];
    for (std::size_t j = 0; j < i; ++j)
      if (data_.triangles[hits[j].primitive].shape == tri.shape &&
          sameSurface(hits[j].t, hits[i].t))
        return true;
    return false;
  }

  // shading.frag's shade(), on the CPU. Shapes inside an active group are lit per pixel, as
  // the group's shading program does; elsewhere Coin's fixed-function GL lights each vertex
  // and interpolates (Gouraud), and so does this.
  glm::vec4 shade(const Triangle& tri, const Hit& hit, const glm::vec3& position,
                  const glm::vec3& rayDirection, RayCounts& rays) const {
    const TextureImage* image = imageOf(data_, tri);
    const SurfaceSample sample = sampleSurface(tri.colour, tri.texCoord, image, hit.u, hit.v);
    glm::vec4 colour = sample.colour;
    if (tri.lit) {
      bool front = glm::dot(tri.geometricNormal, rayDirection) < 0.0f;
      if (tri.clockwise) front = !front;
      const float side = tri.twoSided && !front ? -1.0f : 1.0f;
      const float w = 1.0f - hit.u - hit.v;
      glm::vec3 lit;
      if (tri.group >= 0) {
        const glm::vec3 normal = w * tri.normal[0] + hit.u * tri.normal[1] + hit.v * tri.normal[2];
        lit = lighting(tri, side * normal, position, glm::vec3(colour), rays);
      } else {
        const float weights[3] = {w, hit.u, hit.v};
        lit = glm::vec3(0.0f);
        for (std::size_t i = 0; i < 3; ++i) {
          const glm::vec3& corner =
              data_.positions[std::size_t(&tri - data_.triangles.data()) * 3 + i];
          lit += weights[i] *
                 lighting(tri, side * tri.normal[i], corner, glm::vec3(tri.colour[i]), rays);
        }
      }
      colour = glm::vec4(lit, colour.a);
    }
    colour = texturedColour(colour, sample.texel, image);
    const Material& material = data_.materials[std::size_t(tri.material)];
    if (material.fogType != 0) {
      SbVec3f eye;
      viewing_.multVecMatrix(SbVec3f(position.x, position.y, position.z), eye);
      const float z = std::fabs(eye[2]);
      const float fog =
          material.fogType == 1   ? (material.fogEnd - z) / (material.fogEnd - material.fogStart)
          : material.fogType == 2 ? std::exp(-material.fogDensity * z)
                                  : std::exp(-material.fogDensity * material.fogDensity * z * z);
      colour = glm::vec4(
          glm::mix(material.fogColour, glm::vec3(colour), glm::clamp(fog, 0.0f, 1.0f)), colour.a);
    }
    return colour;
  }

  // Coin's lighting equation at one point, clamped as GL clamps a lit colour.
  glm::vec3 lighting(const Triangle& tri, glm::vec3 normal, const glm::vec3& position,
                     const glm::vec3& diffuse, RayCounts& rays) const {
    const float length = glm::length(normal);
    normal = length > 0.0f ? normal / length : glm::vec3(0.0f, 0.0f, 1.0f);
    const Material& material = data_.materials[std::size_t(tri.material)];
    glm::vec3 lit = material.emission + material.globalAmbient * material.ambient;
    const Group* group = tri.group >= 0 ? &data_.groups[std::size_t(tri.group)] : nullptr;
    const std::vector<int>* sets[2] = {nullptr, nullptr};
    if (group) {
      sets[0] = &group->outsideLights;
      sets[1] = &group->lights;
    } else {
      sets[0] = &data_.lightSets[std::size_t(tri.lightSet)];
    }
    for (const std::vector<int>* set : sets) {
      if (set == nullptr) continue;
      for (int index : *set)
        lit += contribution(data_.lights[std::size_t(index)], tri, group, normal, position, diffuse,
                            material, rays);
    }
    if (group != nullptr && group->bounce && options_.bounceSamples > 0)
      lit += diffuse * indirect(*group, tri, normal, position, rays);
    return glm::clamp(lit, 0.0f, 1.0f);
  }

  // Where a light is seen from `position`: the unit direction towards it and GL's distance
  // and spot attenuation of its light there.
  struct Incidence {
    glm::vec3 toLight;
    float attenuation;
  };
  static Incidence incidence(const Light& light, const glm::vec3& position) {
    if (light.type == LightType::Directional) return {glm::normalize(light.towardsLight), 1.0f};
    const glm::vec3 v = light.position - position;
    const float distance = glm::length(v);
    Incidence in{distance > 0.0f ? v / distance : glm::vec3(0.0f, 0.0f, 1.0f), 1.0f};
    in.attenuation = 1.0f / (light.attenuation.x + light.attenuation.y * distance +
                             light.attenuation.z * distance * distance);
    if (light.type == LightType::Spot) {
      const float spotCos = glm::dot(-in.toLight, glm::normalize(light.spotDirection));
      in.attenuation *=
          spotCos < light.spotCosCutoff ? 0.0f : std::pow(spotCos, light.spotExponent);
    }
    return in;
  }

  bool casts(const Group& group, const Light& light) const {
    return std::find(group.casting.begin(), group.casting.end(),
                     int(&light - data_.lights.data())) != group.casting.end();
  }

  ShadowColourModel modelOf(const Group& group, const Light& light) const {
    return castingColourModel(*light.node,
                              *static_cast<const SoTransparentShadowGroup*>(group.node),
                              group.casters->coloured());
  }

  // The transmittance of the group's casters between `position` (on a surface of geometric
  // normal `normal`) and the light.
  glm::vec3 castersTransmittance(const Group& group, const Light& light, const glm::vec3& position,
                                 const glm::vec3& normal, ShadowColourModel model) const {
    return light.type == LightType::Directional
               ? group.casters->transmittanceTowards(position, normal, light.towardsLight, model)
               : group.casters->transmittance(position, normal, light.position, model);
  }

  glm::vec3 contribution(const Light& light, const Triangle& tri, const Group* group,
                         const glm::vec3& normal, const glm::vec3& position,
                         const glm::vec3& diffuse, const Material& material,
                         RayCounts& rays) const {
    const Incidence in = incidence(light, position);
    const float nDotL = glm::dot(normal, in.toLight);
    if (!(nDotL > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 halfVector = glm::normalize(in.toLight + viewDirection_);
    const float nDotH = std::max(glm::dot(normal, halfVector), 0.0f);
    glm::vec3 direct = nDotL * light.colour * diffuse;
    if (nDotH > 0.0f)
      direct += std::pow(nDotH, material.shininess) * light.colour * material.specular;
    if (group != nullptr && tri.shadowed && group->casters && casts(*group, light)) {
      ++rays.shadow;
      direct *= castersTransmittance(*group, light, position, tri.geometricNormal,
                                     modelOf(*group, light));
    }
    return in.attenuation * direct;
  }

  // One diffuse bounce at `position` (shading normal `normal`, on `tri` in `group`): the mean,
  // over cosine-weighted directions about the normal, of the diffuse light that the group's
  // casting lights put directly on the first opaque surface of the group that way, times the
  // transmittance of the glass between. With Coin's Lambert (no 1 / pi: a light's colour is
  // its irradiance / pi), cosine-weighted sampling leaves the plain mean: L = kd(x) (1 / pi)
  // \int L(y) cos dw. Only the group's opaque, lit surfaces reflect; glass filters.
  glm::vec3 indirect(const Group& group, const Triangle& tri, const glm::vec3& normal,
                     const glm::vec3& position, RayCounts& rays) const {
    if (!group.casters || group.casting.empty()) return glm::vec3(0.0f);
    thread_local std::vector<Hit> hits;
    const int side = int(std::ceil(std::sqrt(double(options_.bounceSamples))));
    // One rotation of the strata per point (Cranley-Patterson), from the point's bits: the
    // picture is the same on every run and has no pattern shared by neighbouring pixels.
    std::uint32_t seed = 2166136261u;
    for (float c : {position.x, position.y, position.z}) {
      std::uint32_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      seed = (seed ^ bits) * 16777619u;
    }
    const auto unit = [&seed] {
      seed ^= seed << 13;
      seed ^= seed >> 17;
      seed ^= seed << 5;
      return float(seed >> 8) * (1.0f / 16777216.0f);
    };
    const float du = unit(), dv = unit();
    const glm::vec3 along = std::fabs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 t1 = glm::normalize(glm::cross(normal, along));
    const glm::vec3 t2 = glm::cross(normal, t1);
    // The surface's own side: directions into it are counted as light that does not come.
    const glm::vec3 front =
        glm::dot(tri.geometricNormal, normal) >= 0.0f ? tri.geometricNormal : -tri.geometricNormal;
    const float scale =
        std::max({std::fabs(position.x), std::fabs(position.y), std::fabs(position.z), 1.0f});
    glm::vec3 sum(0.0f);
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) {
        const float u = std::fmod((float(i) + 0.5f) / float(side) + du, 1.0f);
        const float v = std::fmod((float(j) + 0.5f) / float(side) + dv, 1.0f);
        const float r = std::sqrt(u), phi = 6.28318531f * v;
        const glm::vec3 direction = r * std::cos(phi) * t1 + r * std::sin(phi) * t2 +
                                    std::sqrt(std::max(0.0f, 1.0f - u)) * normal;
        if (!(glm::dot(direction, front) > 0.0f)) continue;
        ++rays.bounce;
        if (!surfacesAlong(position, direction, 1e-5f * scale,
                           std::numeric_limits<float>::infinity(), hits))
          continue;
        const Hit& hit = hits.back();
        const Triangle& reflector = data_.triangles[hit.primitive];
        if (reflector.group != tri.group || !reflector.lit) continue;
        const TextureImage* image = imageOf(data_, reflector);
        const SurfaceSample sample =
            sampleSurface(reflector.colour, reflector.texCoord, image, hit.u, hit.v);
        const glm::vec3 kd = glm::vec3(texturedColour(sample.colour, sample.texel, image));
        const glm::vec3 y = position + hit.t * direction;
        // The geometric normal is the corners' cross product, of any length.
        const glm::vec3 facing = glm::normalize(reflector.geometricNormal);
        const glm::vec3 ny = glm::dot(facing, direction) < 0.0f ? facing : -facing;
        for (int index : group.casting) {
          const Light& light = data_.lights[std::size_t(index)];
          const Incidence in = incidence(light, y);
          const float nDotL = glm::dot(ny, in.toLight);
          if (!(nDotL > 0.0f) || !(in.attenuation > 0.0f)) continue;
          const ShadowColourModel model = modelOf(group, light);
          glm::vec3 through(1.0f);
          for (std::size_t k = 0; k + 1 < hits.size(); ++k) {
            if (metBefore(hits.data(), k)) continue;
            const Triangle& glass = data_.triangles[hits[k].primitive];
            const TextureImage* glassImage = imageOf(data_, glass);
            const SurfaceSample g =
                sampleSurface(glass.colour, glass.texCoord, glassImage, hits[k].u, hits[k].v);
            through *= transmittance(
                glm::clamp(texturedColour(g.colour, g.texel, glassImage), 0.0f, 1.0f), model);
          }
          ++rays.shadow;
          sum += through * kd * light.colour * (nDotL * in.attenuation) *
                 castersTransmittance(group, light, y, reflector.geometricNormal, model);
        }
      }
    return sum / float(side * side);
  }

  const Extraction& data_;
  RTCScene scene_;
  const TraceOptions& options_;
  SbMatrix viewing_;
  SbMatrix worldToClip_;
  SbMatrix clipToWorld_;
  glm::vec3 viewDirection_{0.0f, 0.0f, 1.0f};
};

}  // namespace

struct SceneTracer::Data {
  Extraction extraction;
  EmbreeDevice device;
  EmbreeScene scene;
  std::vector<const SoPath*> untracedPaths;
  int width = 0;
  int height = 0;
};

namespace {

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
    action.addPreCallback(SoTransparentShadowGroup::getClassTypeId(), groupEnter, &data);
    action.addPostCallback(SoTransparentShadowGroup::getClassTypeId(), groupLeave, &data);
    action.addPreCallback(SoShadowStyle::getClassTypeId(), shadowStyle, nullptr);
    action.addPreCallback(SoLight::getClassTypeId(), light, &data);
    action.addPreCallback(SoShape::getClassTypeId(), skipDefectiveShape, nullptr);
    action.addPreCallback(SoShape::getClassTypeId(), shapeStart, &data);
    action.addTriangleCallback(SoShape::getClassTypeId(), triangle, &data);
    action.addLineSegmentCallback(SoShape::getClassTypeId(), lineSegment, &data);
    action.addPointCallback(SoShape::getClassTypeId(), point, &data);
    apply(action);
  }
  for (const CoinRef<SoPath>& path : data.untracedPaths)
    result->untracedPaths.push_back(path.get());
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
  }

  result->scene = buildTriangleScene(
      result->device.get(), data.triangles.size(),
      [&data](std::size_t i) { return &data.positions[i].x; }, cameraFilter, error);
  if (!result->scene) throw std::runtime_error(error);
  return result;
}

bool SceneTracer::updateLights(const SoPath* path) {
  Extraction& data = data_->extraction;
  // Triangles outside any group index light sets of the lights read before.
  if (!data.lightSets.empty()) return false;
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
  placeLights(data);
  return true;
}

bool SceneTracer::viewDependent() const {
  return data_->extraction.fogFollowsView;
}

SceneTracer::SceneTracer(std::unique_ptr<Data> data) : data_(std::move(data)) {}
SceneTracer::~SceneTracer() = default;

std::unique_ptr<SceneTracer> SceneTracer::fromScene(SoNode* root, int width, int height) {
  return std::unique_ptr<SceneTracer>(new SceneTracer(
      extract(width, height, [root](SoCallbackAction& action) { action.apply(root); })));
}

std::unique_ptr<SceneTracer> SceneTracer::fromPath(const SoPath* path, int width, int height) {
  return std::unique_ptr<SceneTracer>(
      new SceneTracer(extract(width, height, [path](SoCallbackAction& action) {
        action.apply(const_cast<SoPath*>(path));
      })));
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
const std::vector<std::string>& SceneTracer::untracedShapes() const {
  return data_->extraction.untracedShapes;
}
const std::vector<const SoPath*>& SceneTracer::untracedPaths() const {
  return data_->untracedPaths;
}

bool SceneTracer::trace(const TraceOptions& options, TracedPixels& out) const {
  return trace(viewing(), projection(), nullptr, options, out);
}

bool SceneTracer::trace(const SbMatrix& viewing, const SbMatrix& projection,
                        const float* depthLimit, const TraceOptions& options,
                        TracedPixels& out) const {
  const std::size_t pixels = std::size_t(options.width) * std::size_t(options.height);
  out.width = options.width;
  out.height = options.height;
  out.rgba.assign(pixels * 4, 0.0f);
  out.depth.assign(pixels, 1.0f);
  out.cameraRays = 0;
  out.shadowRays = 0;
  out.bounceRays = 0;
  for (std::size_t i = 0; i < pixels; ++i) out.rgba[i * 4 + 3] = 1.0f;
  const Tracer tracer(data_->extraction, data_->scene.get(), viewing, projection, options);
  const int workers = workerCount(options.threads);
  std::vector<std::vector<Hit>> hits(static_cast<std::size_t>(workers));
  std::vector<RayCounts> rays(static_cast<std::size_t>(workers));
  SurfacesMet* kept = options.surfaces;
  const bool reuse = kept != nullptr && options.reuseSurfaces && options.height > 0 &&
                     kept->rows.size() == std::size_t(options.height) &&
                     kept->rows.front().ends.size() == std::size_t(options.width);
  if (kept != nullptr && !reuse) kept->rows.resize(std::size_t(options.height));
  parallelRows(
      options.height, workers,
      [&](int y, int worker) {
        const std::size_t row = std::size_t(y) * std::size_t(options.width);
        // GL's rows run bottom to top.
        const float* limits =
            depthLimit != nullptr
                ? depthLimit + std::size_t(options.height - 1 - y) * std::size_t(options.width)
                : nullptr;
        std::vector<Hit>& found = hits[std::size_t(worker)];
        SurfacesMet::Row* keptRow = kept != nullptr ? &kept->rows[std::size_t(y)] : nullptr;
        if (keptRow != nullptr && !reuse) {
          keptRow->hits.clear();
          keptRow->ends.resize(std::size_t(options.width));
          keptRow->depth.resize(std::size_t(options.width));
        }
        for (int x = 0; x < options.width; ++x) {
          const Tracer::CameraRay ray = tracer.cameraRay(x, y);
          PixelResult p;
          if (reuse) {
            const std::uint32_t begin = x > 0 ? keptRow->ends[std::size_t(x) - 1] : 0u;
            p = tracer.composite(ray, keptRow->hits.data() + begin,
                                 keptRow->ends[std::size_t(x)] - begin,
                                 keptRow->depth[std::size_t(x)], rays[std::size_t(worker)]);
          } else {
            const float depth = tracer.visible(ray, limits != nullptr ? limits[x] : 1.0f, found);
            p = tracer.composite(ray, found.data(), found.size(), depth, rays[std::size_t(worker)]);
            if (keptRow != nullptr) {
              keptRow->hits.insert(keptRow->hits.end(), found.begin(), found.end());
              keptRow->ends[std::size_t(x)] = std::uint32_t(keptRow->hits.size());
              keptRow->depth[std::size_t(x)] = depth;
            }
          }
          float* rgba = &out.rgba[(row + std::size_t(x)) * 4];
          rgba[0] = p.colour.r;
          rgba[1] = p.colour.g;
          rgba[2] = p.colour.b;
          rgba[3] = p.transmitted;
          out.depth[row + std::size_t(x)] = p.depth;
        }
        if (options.rowsDone) ++*options.rowsDone;
      },
      options.cancel);
  // A cancelled trace leaves rows it did not reach: nothing kept may be reused.
  if (options.cancel && options.cancel->load()) {
    if (kept != nullptr) kept->rows.clear();
    return false;
  }
  if (!reuse) out.cameraRays = pixels;
  for (const RayCounts& count : rays) {
    out.shadowRays += count.shadow;
    out.bounceRays += count.bounce;
  }
  return true;
}

}  // namespace ivshadow
