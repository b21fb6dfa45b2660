#pragma once

#include "ivshadow/Export.h"
#include "scene/ShadowTypes.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ivshadow {

struct SceneTriangles;

// Transparent shadow volumes (seeds/003, after Kim et al. 2007): the light reaching a point
// is the product of the transmittances of the casters' surfaces between it and the light,
// so the sum of log transmittance over the volumes holding the point is its log visibility.
//
// Every caster triangle, turned to face the light, bounds a volume: itself (near cap), its
// edges extruded away from the light past every receiver, and its image there (far cap). The
// extrusion is finite, not to infinity (w = 0), because an orthographic camera sees a point
// at infinity nowhere on the screen: the far caps, through which a ray from a receiver leaves
// a widening volume, would never be drawn. Of the
// edges only the sums are drawn: an edge shared by triangles that turn it opposite ways with
// equal weights cancels, and what is left of a shared edge is one quad weighted by the sum
// of its triangles' signed weights (the "multiplicity" of the document, here per channel,
// so one shape of many colours or an open or inconsistently oriented mesh needs no special
// case). Edges are shared where corners are bitwise equal, as Coin generates them for the
// vertices of one mesh. Summing is linear, so the faces are the sum of closed per-triangle
// volumes whatever is merged: a T-junction (one mesh's corner on another's edge) needs no
// splitting, as each triangle's own volume stays closed over its own corners. Faces are
// wound counter-clockwise seen from outside the volume. Each corner's far image depends on
// the corner alone, so shared edges stay watertight.
class IVSHADOW_INTERNAL ShadowVolumes {
 public:
  // Takes the casters' edges and their colours once; build() then serves any light.
  ShadowVolumes(const SceneTriangles& casters, ShadowColourModel model);

  // How far beyond the farthest receiver a point light's volumes reach, as a factor of that
  // distance. A far cap is flat, so it comes nearer the light than its corners do, to
  // cos(half the angle the caster subtends) of their distance: 64 keeps every receiver inside
  // for triangles subtending up to 178 degrees from the light. The cost is float precision
  // where the side faces pass the receivers (64 times the scene's rounding, 4e-6 of its
  // size); the bundled scenes give the same picture at 4 and at 64, and the same time.
  static constexpr float kReach = 64.0f;

  // The faces of the volumes for a light at `light` (a point light) or, `directional`, in the
  // unit direction `light` towards it, as triangles (three vertices each) into `out`
  // (cleared first; its memory is reused). Every receiver lies in the box `low`..`high`
  // (the volumes reach past it and past the casters).
  void build(const glm::vec3& light, bool directional, const glm::vec3& low, const glm::vec3& high,
             std::vector<VolumeVertex>& out) const;

  // Triangles whose colour varies across them (per-vertex colours) or that are textured:
  // their volume carries one colour, their corners' mean with the texture's mean texel.
  std::size_t approximatedTriangles() const { return approximated_; }
  std::size_t triangleCount() const { return weights_.size(); }
  std::size_t edgeCount() const { return edges_.size(); }

 private:
  void buildEdges();

  struct Edge {
    std::uint32_t from, to;  // welded corner indices, from < to
    // The triangles on the edge: index and +1 if the triangle runs from -> to, else -1.
    std::uint32_t firstSide, sideCount;
  };
  std::vector<glm::vec3> corners_;        // welded positions
  glm::vec3 low_{0.0f}, high_{0.0f};      // their bounds
  std::vector<std::uint32_t> triangles_;  // three welded corners per triangle
  std::vector<glm::vec3> weights_;        // per triangle: log transmittance, <= 0
  std::vector<Edge> edges_;
  std::vector<std::pair<std::uint32_t, int>> sides_;
  std::size_t approximated_ = 0;
};

}  // namespace ivshadow
