#pragma once

#include <functional>
#include <string>

class SoGLRenderAction;
class SoNode;

namespace ivshadow {

class GroupShading;
class PeelPass;
struct PeelStatistics;

// How a subgraph is peeled: SoPeelingSeparator's fields, or the choice of a peeling
// SoTransparentShadowGroup.
struct PeelOptions {
  bool dual = true;              // nearest and farthest layer per pass, else nearest only
  int maxPasses = 0;             // 0: until nothing is left (SoPeelingSeparator::kMaxPasses)
  bool earlyTermination = true;  // stop when a pass found nothing deeper
  // One pass into per-pixel fragment lists (FragmentListPass) instead of peeling; a view the
  // lists cannot hold is peeled as above.
  bool fragmentLists = false;
  // The node peeling, for its warnings (one per node and reason).
  const SoNode* owner = nullptr;
};

// Draws a subgraph's opaque surfaces into the framebuffer, then peels its transparent ones
// and composites them over it in exact per-pixel depth order (docs/PEELING.md), each pass
// shaded by a variant of `shading`, whose frame the caller has begun. `draw` draws the
// subgraph once, as a plain separator would. With early termination, a view in which the
// opaque pass met no transparent fragment is finished after that pass (no peel pass). The
// last frame's passes and times go into `statistics`. Used by SoPeelingSeparator and by
// SoTransparentShadowGroup's default transparency. Returns empty; or, when GL could not make
// the peel targets for this viewport, what it said, having drawn nothing: the caller then
// draws the subgraph with Coin's blending.
std::string peelSubgraph(SoGLRenderAction* action, PeelPass& pass, GroupShading& shading,
                         const PeelOptions& options,
                         const std::function<void(SoGLRenderAction*)>& draw,
                         PeelStatistics& statistics);

}  // namespace ivshadow
