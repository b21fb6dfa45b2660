#pragma once

#include "scene/CoinRef.h"

class SbViewportRegion;
class SoNode;
class SoSeparator;

namespace ivshadow {

// A scene made ready to render the way Coin's viewers show it: when the scene has no active
// camera, a perspective camera is added and viewAll() fits it to the scene; when it has no
// active light, a headlight (a directional light fixed to the camera, as SoQt viewers add)
// is put first in the graph.
struct ViewSetup {
  CoinRef<SoSeparator> root;
  bool addedCamera = false;
  bool addedHeadlight = false;

  // Whether `scene` turns on a light of its own (not under a switched-off switch). The CLI
  // and the viewer add a headlight only to scenes that do not.
  static bool hasActiveLight(SoNode* scene);
  static ViewSetup prepare(SoNode* scene, const SbViewportRegion& viewport);
};

}  // namespace ivshadow
