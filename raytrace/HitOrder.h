#pragma once

// The order of the surfaces a camera ray collected (SceneTracer's camera rays and bounce
// rays): in exact depth order, ended at the opaque surface where there is one.

#include "raytrace/SceneTracer.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace ivshadow::detail {

// The transparent hits at or past `t` left out: those behind the opaque surface there.
inline void dropFrom(std::vector<SurfacesMet::Hit>& hits, float t) {
  hits.erase(
      std::remove_if(hits.begin(), hits.end(), [t](const SurfacesMet::Hit& h) { return h.t >= t; }),
      hits.end());
}

// The transparent surfaces a ray collected in exact depth order, coincident ones in the order
// Coin traversed them. A pixel holds a few: sorted by insertion, as std::sort sorts up to 16
// elements, in the same order, without its calls (which were a tenth of a moving camera's
// trace through 8 sheets of glass).
inline void inDepthOrder(std::vector<SurfacesMet::Hit>& hits) {
  using Hit = SurfacesMet::Hit;
  const auto before = [](const Hit& a, const Hit& b) {
    return a.t != b.t ? a.t < b.t : a.primitive < b.primitive;
  };
  if (hits.size() > 16) {
    std::sort(hits.begin(), hits.end(), before);
    return;
  }
  for (std::size_t i = 1; i < hits.size(); ++i) {
    const Hit hit = hits[i];
    std::size_t j = i;
    for (; j > 0 && before(hit, hits[j - 1]); --j) hits[j] = hits[j - 1];
    hits[j] = hit;
  }
}

// The transparent surfaces a ray collected, put in exact depth order and ended at the opaque
// surface `nearest` where `opaque`.
inline void inDepthOrder(std::vector<SurfacesMet::Hit>& hits, bool opaque,
                         const SurfacesMet::Hit& nearest) {
  if (opaque) dropFrom(hits, nearest.t);
  inDepthOrder(hits);
  if (opaque) hits.push_back(nearest);
}

}  // namespace ivshadow::detail
