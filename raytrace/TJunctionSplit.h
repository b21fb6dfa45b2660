#pragma once

#include "ivshadow/Export.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <utility>
#include <vector>

namespace ivshadow {

// Makes a triangle mesh conforming where it has T-junctions: a corner of one triangle lying
// on an edge of another (a tall quad beside two short ones, as walls around a window are
// often modelled). Rasterising faces that meet at a T-junction leaves pixels along the edge
// that neither or both cover, since the long edge and the short ones round differently;
// split at the corner, every edge is shared by faces with the same two corners.
//
// Searches the edges in `open` (pairs of corner indices; those without a matching edge on
// the other side, where a T-junction can be) for corners of `corners` lying on them (within
// 1e-5 of the edge's length, which bends an edge by no more than that), and replaces each
// triangle of `triangles` (three corner indices each) with such an edge by a fan over its
// corners and the ones found: from the opposite corner when one edge is split, else from a
// new corner at the centroid (appended to `corners`). Returns, for each triangle now in
// `triangles`, the index of the triangle it came from.
IVSHADOW_INTERNAL std::vector<std::uint32_t> splitTJunctions(
    std::vector<glm::vec3>& corners, std::vector<std::uint32_t>& triangles,
    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& open);

}  // namespace ivshadow
