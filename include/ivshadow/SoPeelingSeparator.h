#pragma once

#include "ivshadow/Export.h"

#include <Inventor/fields/SoSFBool.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFInt32.h>
#include <Inventor/nodes/SoSeparator.h>

namespace ivshadow {
class PeelingSeparatorImpl;
struct PeelStatistics;
}  // namespace ivshadow

/*!
  \class SoPeelingSeparator
  A separator whose transparent children are composited in exact depth order per pixel, by
  depth peeling, whatever their traversal order: interpenetrating and self-overlapping
  transparent surfaces, textured transparency and per-vertex alpha come out right.

  Opaque children are drawn once as usual. Transparent fragments are then peeled layer by
  layer and composited over them (Rejent 2014, eq. 2.5-2.8): with DUAL, the nearest and the
  farthest remaining layer per pass (N layers in N/2 + 1 passes, Bavoil & Myers 2008); with
  FRONT_TO_BACK one layer per pass. FRAGMENT_LISTS draws the transparent surfaces once, each
  fragment shaded and linked into its pixel's list, then sorts each list by depth and
  composites it (an A-buffer): the same picture in one pass whatever the layers; maxPasses and
  earlyTermination do not apply. A view in which a pixel holds more than 32 transparent
  surfaces, or whose fragments do not fit in GL's storage, is peeled with DUAL instead (one
  warning). Coin's transparency type is overridden inside the separator. Inside a
  SoTransparentShadowGroup every peeled layer is shaded with the group's deep shadows.

  TRACER takes the children's triangles away from GL: Embree traces every pixel's ray through
  them on the CPU and composites every surface it meets in exact depth order (the reference
  renderer's code, `ivshadow reference`, lit per pixel as the separator's own program lights),
  from the near plane to the depth GL drew before the separator; the picture is blended onto
  the framebuffer with the depth of its nearest opaque surface. While the children, the state
  above, the camera, the viewport and the depth drawn before stay the same, a frame draws the
  picture it kept without tracing. Lines, points and screen-aligned text are drawn by GL after
  it, depth-tested against it. AUTO chooses per GL context: TRACER where GL is a software
  rasteriser (Mesa's llvmpipe), whose per-fragment programs cost more than the trace,
  FRAGMENT_LISTS on a GPU; it says which once. Inside a SoTransparentShadowGroup both peel
  with FRAGMENT_LISTS, shaded with the group's shadows (the group's own `renderer TRACER`
  traces its whole subgraph, this separator's children included).

  FILE FORMAT/DEFAULTS:
  \code
    PeelingSeparator {
        renderCaching AUTO
        boundingBoxCaching AUTO
        renderCulling AUTO
        pickCulling AUTO
        method FRAGMENT_LISTS   # FRAGMENT_LISTS, DUAL, FRONT_TO_BACK, TRACER or AUTO
        maxPasses 0             # passes per frame, the first finding the depth range;
                                #   0: until no layer is left, at most 64
        earlyTermination TRUE   # stop when a pass found no deeper layer; FALSE always runs
                                #   maxPasses (64 when 0)
    }
  \endcode
*/
class IVSHADOW_API SoPeelingSeparator : public SoSeparator {
  typedef SoSeparator inherited;
  SO_NODE_HEADER(SoPeelingSeparator);

 public:
  static void initClass();
  SoPeelingSeparator();

  enum Method {
    DUAL,            //!< nearest and farthest layer per pass
    FRONT_TO_BACK,   //!< nearest layer per pass
    FRAGMENT_LISTS,  //!< one pass into per-pixel fragment lists, sorted and composited after
    TRACER,          //!< Embree traces the children on the CPU; GL draws the picture
    // TRACER on a software rasteriser, FRAGMENT_LISTS on a GPU (file name: AUTO; SoSeparator's
    // CacheEnabled has AUTO).
    AUTO_METHOD
  };

  //! Hard limit on passes per frame, whatever maxPasses says.
  static constexpr int kMaxPasses = 64;

  SoSFEnum method;
  SoSFInt32 maxPasses;
  SoSFBool earlyTermination;

  //! Passes and peel time of the last frame rendered in any context.
  const ivshadow::PeelStatistics& getStatistics() const;

  void GLRenderBelowPath(SoGLRenderAction* action) override;
  void GLRenderInPath(SoGLRenderAction* action) override;
  void notify(SoNotList* list) override;

 protected:
  ~SoPeelingSeparator() override;

 private:
  ivshadow::PeelingSeparatorImpl* impl_;
};
