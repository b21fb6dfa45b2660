#pragma once

// What SceneTracer's two halves share: the scene as read through the callback action
// (raytrace/SceneExtraction.cpp) and traced with Embree (raytrace/SceneTracer.cpp).

#include "raytrace/CasterScene.h"
#include "raytrace/EmbreeHandles.h"
#include "raytrace/SceneTracer.h"
#include "scene/CoinRef.h"
#include "scene/SceneTriangles.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/SbVec3f.h>
#include <Inventor/SoPath.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

class SoLight;
class SoNode;

namespace ivshadow {
namespace detail {

inline glm::vec3 toGlm(const SbVec3f& v) {
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
  // From the root: its casters are taken in the state in force there. Released once they are
  // (a path holds a reference to every node on it, the group's ancestors included, and this
  // extraction is kept by the group's own tracer: the scene would never be freed).
  CoinRef<SoPath> path;
  std::vector<int> lights;   // every light turned on in the group's subgraph
  std::vector<int> casting;  // those that cast (raytrace/CastingLight.h), as many as GL's
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

// What a triangle's colour alone makes of every point of it, decided once it is read
// (CameraFilter.h's coverageOf) rather than for every hit a camera ray meets: Sampled where a
// texture takes part or the corners' alphas come near a threshold, and each point's interpolated
// alpha decides.
enum class Coverage : std::uint8_t { Sampled, Transparent, Opaque, Clear };

struct Triangle {
  glm::vec3 normal[3];
  glm::vec4 colour[3];
  glm::vec2 texCoord[3];
  glm::vec3 geometricNormal;  // from the winding: counter-clockwise front
  int material = 0;
  int texture = -1;
  int lightSet = -1;  // the lights in force where it is drawn (Extraction::lightSets)
  int group = -1;     // innermost active SoTransparentShadowGroup
  bool lit = true;
  bool twoSided = false;
  bool clockwise = false;
  bool shadowed = false;
  // GL's polygon offset where it is drawn (SoPolygonOffset on filled faces): factor and
  // units, 0 none.
  float offsetFactor = 0.0f;
  float offsetUnits = 0.0f;
  // Lit per pixel, as a group's or a peeling separator's shading program lights it (else per
  // vertex, as Coin's fixed-function GL does): inside a group or a SoPeelingSeparator.
  bool perPixel = false;
  Coverage coverage = Coverage::Sampled;
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
  int peelingDepth = 0;                          // SoPeelingSeparators being traversed
  std::map<const SoNode*, std::string> skipped;  // shapes without triangles
  std::vector<std::string> untracedShapes;       // their names, in traversal order
  // And the way to every instance: the child index at each level of its path (index 0, the
  // head's, unused). Indices, not SoPaths: a path holds a reference to every node on it, and
  // this extraction is kept by the group's tracer, so the scene would never be freed.
  std::vector<std::vector<int>> untracedPaths;
  std::uint32_t untracedShape = ~0u;  // the instance (shape) a path was kept for
  SbMatrix viewing = SbMatrix::identity();
  SbMatrix projection = SbMatrix::identity();
  bool haveCamera = false;
  std::uint32_t shape = 0;
  // Some fog's distance is the view volume's depth (visibility 0): a moved camera changes it.
  bool fogFollowsView = false;
  // The TextureCoordinateEnvironment nodes met (their ids): shapes below one take GL's sphere
  // map, from their eye-space positions and normals, so a moved camera changes them too.
  std::vector<SbUniqueId> environmentFunctions;
  bool texCoordsFollowView = false;
  // A pass that reads only the lights again (SceneTracer::updateLights): the groups met are
  // the ones read before, in the same order.
  bool lightsOnly = false;
  std::size_t groupsMet = 0;
  bool groupsChanged = false;  // ... and they were not
};

// The texture triangle `tri` shows, or null.
inline const TextureImage* imageOf(const Extraction& data, const Triangle& tri) {
  return tri.texture >= 0 ? &data.textures[std::size_t(tri.texture)] : nullptr;
}

}  // namespace detail

struct SceneTracer::Data {
  detail::Extraction extraction;
  EmbreeDevice device;
  EmbreeScene scene;
  int packetWidth = 1;  // the device's native packet width (nativePacketWidth)
  int width = 0;
  int height = 0;
};

}  // namespace ivshadow
