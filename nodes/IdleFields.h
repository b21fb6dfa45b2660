#pragma once

#include "ivshadow/ShadowMethod.h"

#include <map>
#include <string>

class SoNode;
class SoLight;
class SoTransparentShadowGroup;

namespace ivshadow {

// The shadow fields (nodes/ShadowFieldTable.h) that act only on some paths: a map's fields do
// nothing to a light whose shadows are traced (RAYS, VOLUMES), and no light's method or map
// field acts in a group that traces its children (renderer TRACER, or AUTO on a software
// rasteriser). A field the user set where it cannot act is said once per node and field, so
// that a setting that does nothing never passes for one that does.
class IdleFields {
 public:
  // The node whose shadow fields `light` casts with in `group` (castingSettings' choice): the
  // light itself for the deep shadow lights, the group for any other light.
  static SoNode& owner(SoLight& light, SoTransparentShadowGroup& group);

  // A frame of GL's path: `light` cast with `method` (resolved).
  void used(SoLight& light, SoTransparentShadowGroup& group, ShadowMethod method);
  // After the frame's lights: every field set on their owners that none of the methods used
  // reads is said.
  void say();
  // A traced frame: neither the method nor any map field of `light`'s owner acts; `why` says
  // what the group does instead.
  static void traced(SoLight& light, SoTransparentShadowGroup& group, const std::string& why);
  // Says, once per node and field, that `field`, when the user set it, does nothing: `why`.
  static void sayIfSet(SoNode& node, const char* field, const std::string& why);

 private:
  // Per owner: a bit per method used this frame.
  std::map<SoNode*, unsigned> methods_;
};

}  // namespace ivshadow
