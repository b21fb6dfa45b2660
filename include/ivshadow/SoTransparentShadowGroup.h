#pragma once

#include "ivshadow/Export.h"

#include <Inventor/fields/SoSFBool.h>
#include <Inventor/nodes/SoSeparator.h>

namespace ivshadow {
class TransparentShadowGroupImpl;
struct DeepShadowStatistics;
}  // namespace ivshadow

/*!
  \class SoTransparentShadowGroup
  A separator whose subgraph is rendered with shadows from every SoDeepShadowLight in it:
  shadows whose strength follows each caster's opacity and whose colour follows its colour.

  Each deep shadow light in the subgraph gets a cube deep shadow map built by depth peeling
  from the light; the map is rebuilt only when something under the group changed. The
  children are rendered with a per-pixel version of Coin's own lighting in which each deep
  shadow light's contribution is multiplied by the visibility in its map. SoShadowStyle is
  honoured as by SoShadowGroup: only shapes whose style includes CASTS_SHADOW go into the
  maps, and only shapes whose style includes SHADOWED receive shadows. Like SoShadowGroup,
  the group treats every light found in its subgraph as lighting all of it.

  The state in force where the group is traversed applies to its casters as it does to what
  Coin draws: a Material, BaseColor, Complexity, Texture2, Units, DrawStyle, ShapeHints,
  LightModel or SoShadowStyle set above the group, outside it (unlike SoShadowGroup, which
  resets the shadow style at the group). Casters and lights are kept in the group's
  coordinates, so transforms above move both. A change above the group is seen in the next
  frame (see docs/DEEP_SHADOWS.md, "State inherited from above the group").

  FILE FORMAT/DEFAULTS:
  \code
    TransparentShadowGroup {
        renderCaching AUTO
        boundingBoxCaching AUTO
        renderCulling AUTO
        pickCulling AUTO
        isActive TRUE   # FALSE renders the children like a plain SoSeparator
    }
  \endcode
*/
class IVSHADOW_API SoTransparentShadowGroup : public SoSeparator {
  typedef SoSeparator inherited;
  SO_NODE_HEADER(SoTransparentShadowGroup);

 public:
  static void initClass();
  SoTransparentShadowGroup();

  SoSFBool isActive;

  //! What the last render in any context did: per light, layers used per face, map bytes,
  //! build time, and how many times the maps were rebuilt since the group was created.
  const ivshadow::DeepShadowStatistics& getStatistics() const;

  void GLRenderBelowPath(SoGLRenderAction* action) override;
  void GLRenderInPath(SoGLRenderAction* action) override;
  void notify(SoNotList* list) override;

 protected:
  ~SoTransparentShadowGroup() override;

 private:
  ivshadow::TransparentShadowGroupImpl* impl_;
};
