#pragma once

#include "ivshadow/Export.h"

#include <Inventor/fields/SoSFBool.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/nodes/SoSeparator.h>

namespace ivshadow {
class TransparentShadowGroupImpl;
struct DeepShadowStatistics;
struct PeelStatistics;
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

  Transparent surfaces in the subgraph are composited in exact per-pixel depth order by
  default (transparency PEELED): the children are drawn once for the opaque surfaces and
  then peeled two layers per pass (dual depth peeling, as SoPeelingSeparator's DUAL), every
  layer shaded with the group's shadows, whatever Coin's transparency type. A frame whose
  view shows no transparent fragment draws the children once, as Coin would. A
  SoPeelingSeparator inside a peeling group draws its children as part of the group's
  peeling (one peeling per pixel: its own fields do not apply there), and so does a group
  inside a peeling (shaded by the enclosing group's or separator's shading). COIN_BLENDING
  leaves transparency to Coin (the action's transparency type, in traversal order), as
  before.

  FILE FORMAT/DEFAULTS:
  \code
    TransparentShadowGroup {
        renderCaching AUTO
        boundingBoxCaching AUTO
        renderCulling AUTO
        pickCulling AUTO
        isActive TRUE   # FALSE renders the children like a plain SoSeparator
        transparency PEELED  # PEELED: transparent surfaces in exact depth order per pixel;
                             #   COIN_BLENDING: Coin's transparency type, traversal order
    }
  \endcode
*/
class IVSHADOW_API SoTransparentShadowGroup : public SoSeparator {
  typedef SoSeparator inherited;
  SO_NODE_HEADER(SoTransparentShadowGroup);

 public:
  static void initClass();
  SoTransparentShadowGroup();

  enum Transparency {
    PEELED,        //!< exact per-pixel depth order, by dual depth peeling
    COIN_BLENDING  //!< Coin's transparency type (order-dependent)
  };

  SoSFBool isActive;
  SoSFEnum transparency;

  //! What the last render in any context did: per light, layers used per face, map bytes,
  //! build time, and how many times the maps were rebuilt since the group was created.
  const ivshadow::DeepShadowStatistics& getStatistics() const;
  //! Passes and time of the last frame's peeling in any context (transparency PEELED).
  const ivshadow::PeelStatistics& getPeelStatistics() const;

  void GLRenderBelowPath(SoGLRenderAction* action) override;
  void GLRenderInPath(SoGLRenderAction* action) override;
  void notify(SoNotList* list) override;

 protected:
  ~SoTransparentShadowGroup() override;

 private:
  ivshadow::TransparentShadowGroupImpl* impl_;
};
