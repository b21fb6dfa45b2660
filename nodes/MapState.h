#pragma once

#include "gl/GlLimits.h"
#include "gl/MapFrame.h"
#include "ivshadow/ShadowMethod.h"
#include "nodes/DeepShadowSettings.h"
#include "raytrace/CastingLight.h"

#include <Inventor/SbVec3f.h>

#include <array>

namespace ivshadow {

// What one light slot of a shadow group holds in one GL context: the light's settings and
// position in the group's coordinates, how its shadow is coloured, whether it is traced, and
// for a map, its depth range and where each face's layers are stored.
struct MapState {
  LightKind kind = LightKind::Point;
  SbVec3f position;  // for a directional light: the unit direction towards it
  SbVec3f axis;      // a spot light's (CastingLight)
  float cutOffAngle = 0.0f;
  DeepShadowSettings settings;
  bool coloured = false;
  float nearRadius = 0.0f;  // the map's depth range along its axes
  float farRadius = 0.0f;
  // An opacity map's sliced distances along the axes: within the depth range, fitted to the
  // transparent casters (fitSlices).
  float sliceNear = 0.0f;
  float sliceFar = 0.0f;
  MapFrame frame;  // the faces the map is built over (fitMapFrame)
  // A directional light's map: the rectangle across the light it covers, coordinates along
  // orthographicBasis (z: the depth range); fitted to the casters and what the view shows.
  glm::vec3 coveredLow{0.0f};
  glm::vec3 coveredHigh{0.0f};
  std::array<int, 6> faceFirst{};
  std::array<int, 6> faceLayers{};
  // The method it casts with, resolved (never Auto): a deep shadow map, an opacity map
  // (OpacityMap), or per pixel (shadowsPerPixel: traced, or drawn by shadow volumes).
  ShadowMethod method = ShadowMethod::Map;
  ShadowColourModel model = ShadowColourModel::Monochrome;
};

}  // namespace ivshadow
