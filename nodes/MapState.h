#pragma once

#include "callbacks/GlLimits.h"
#include "nodes/CastingLight.h"
#include "nodes/DeepShadowSettings.h"

#include <Inventor/SbVec3f.h>

#include <array>

namespace ivshadow {

// What one light slot of a shadow group holds in one GL context: the light's settings and
// position in the group's coordinates, how its shadow is coloured, whether it is traced, and
// for a map, its depth range and where each face's layers are stored.
struct MapState {
  LightKind kind = LightKind::Point;
  SbVec3f position;  // for a directional light: the unit direction towards it
  DeepShadowSettings settings;
  bool coloured = false;
  float nearRadius = 0.0f;
  float farRadius = 0.0f;
  std::array<int, 6> faceFirst{};
  std::array<int, 6> faceLayers{};
  bool rays = false;  // method RAYS: no map, traced per pixel
  ShadowColourModel model = ShadowColourModel::Monochrome;
};

}  // namespace ivshadow
