#include "raytrace/TJunctionSplit.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace ivshadow {
namespace {

constexpr float kOnEdge = 1e-5f;  // relative to the edge's length

// The corners in a uniform grid of about one corner per cell.
class CornerGrid {
 public:
  explicit CornerGrid(const std::vector<glm::vec3>& corners) : corners_(corners) {
    glm::vec3 low(0.0f), high(0.0f);
    for (std::size_t i = 0; i < corners.size(); ++i) {
      low = i == 0 ? corners[i] : glm::min(low, corners[i]);
      high = i == 0 ? corners[i] : glm::max(high, corners[i]);
    }
    low_ = low;
    const float diagonal = glm::length(high - low);
    cell_ = std::max(diagonal / std::cbrt(float(std::max<std::size_t>(corners.size(), 1))),
                     diagonal * 1e-6f + 1e-30f);
    for (std::uint32_t i = 0; i < corners.size(); ++i) cells_[key(cellOf(corners[i]))].push_back(i);
  }

  // Corners lying strictly inside the edge a-b, sorted from a to b.
  std::vector<std::uint32_t> onEdge(std::uint32_t a, std::uint32_t b) const {
    const glm::vec3 pa = corners_[a], pb = corners_[b];
    const glm::vec3 along = pb - pa;
    const float length2 = glm::dot(along, along);
    std::vector<std::pair<float, std::uint32_t>> found;
    if (!(length2 > 0.0f)) return {};
    const float length = std::sqrt(length2);
    // Samples half a cell apart, each with its cell's neighbours: every cell the edge passes
    // through or comes within a tolerance of.
    const int steps = int(std::ceil(length / (0.5f * cell_))) + 1;
    std::vector<long long> visited;
    for (int s = 0; s <= steps; ++s) {
      const glm::ivec3 c = cellOf(pa + along * (float(s) / float(steps)));
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            const long long k = key(c + glm::ivec3(dx, dy, dz));
            if (std::find(visited.begin(), visited.end(), k) != visited.end()) continue;
            visited.push_back(k);
            const auto it = cells_.find(k);
            if (it == cells_.end()) continue;
            for (std::uint32_t w : it->second) {
              if (w == a || w == b) continue;
              const float t = glm::dot(corners_[w] - pa, along) / length2;
              if (!(t > 0.0f && t < 1.0f)) continue;
              if (glm::length(corners_[w] - (pa + along * t)) > kOnEdge * length) continue;
              if (corners_[w] == pa || corners_[w] == pb) continue;
              found.emplace_back(t, w);
            }
          }
    }
    std::sort(found.begin(), found.end());
    std::vector<std::uint32_t> out;
    for (const auto& [t, w] : found) out.push_back(w);
    return out;
  }

 private:
  glm::ivec3 cellOf(const glm::vec3& p) const { return glm::ivec3(glm::floor((p - low_) / cell_)); }
  static long long key(const glm::ivec3& c) {
    return (static_cast<long long>(c.x & 0x1fffff) << 42) |
           (static_cast<long long>(c.y & 0x1fffff) << 21) | static_cast<long long>(c.z & 0x1fffff);
  }

  const std::vector<glm::vec3>& corners_;
  glm::vec3 low_{0.0f};
  float cell_ = 1.0f;
  std::unordered_map<long long, std::vector<std::uint32_t>> cells_;
};

}  // namespace

std::vector<std::uint32_t> splitTJunctions(
    std::vector<glm::vec3>& corners, std::vector<std::uint32_t>& triangles,
    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& open) {
  const std::size_t count = triangles.size() / 3;
  std::vector<std::uint32_t> origin(count);
  for (std::uint32_t t = 0; t < count; ++t) origin[t] = t;
  if (open.empty()) return origin;
  // The corners inside each open edge, from its lower corner index to its higher.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> inside;
  {
    const CornerGrid grid(corners);
    for (const auto& [a, b] : open) {
      std::vector<std::uint32_t> on = grid.onEdge(std::min(a, b), std::max(a, b));
      if (!on.empty())
        inside.emplace(std::make_pair(std::min(a, b), std::max(a, b)), std::move(on));
    }
  }
  if (inside.empty()) return origin;

  std::vector<std::uint32_t> out;
  std::vector<std::uint32_t> outOrigin;
  out.reserve(triangles.size());
  for (std::uint32_t t = 0; t < count; ++t) {
    const std::uint32_t* c = &triangles[std::size_t(t) * 3];
    // The triangle's outline with the corners found on its edges, in its winding.
    std::vector<std::uint32_t> outline;
    int splitEdges = 0, splitEdge = 0;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = c[k], b = c[(k + 1) % 3];
      outline.push_back(a);
      const auto it = inside.find(std::make_pair(std::min(a, b), std::max(a, b)));
      if (it == inside.end()) continue;
      ++splitEdges;
      splitEdge = k;
      if (a < b)
        outline.insert(outline.end(), it->second.begin(), it->second.end());
      else
        outline.insert(outline.end(), it->second.rbegin(), it->second.rend());
    }
    const auto emit = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r) {
      out.insert(out.end(), {p, q, r});
      outOrigin.push_back(t);
    };
    if (splitEdges == 0) {
      emit(c[0], c[1], c[2]);
      continue;
    }
    if (splitEdges == 1) {
      // A fan from the corner opposite the split edge: no triangle of three corners in a row.
      const std::uint32_t apex = c[(splitEdge + 2) % 3];
      const auto start = std::find(outline.begin(), outline.end(), apex) - outline.begin();
      const std::size_t n = outline.size();
      for (std::size_t i = 1; i + 1 < n; ++i)
        emit(apex, outline[(std::size_t(start) + i) % n],
             outline[(std::size_t(start) + i + 1) % n]);
      continue;
    }
    const std::uint32_t centre = std::uint32_t(corners.size());
    corners.push_back((corners[c[0]] + corners[c[1]] + corners[c[2]]) / 3.0f);
    for (std::size_t i = 0; i < outline.size(); ++i)
      emit(centre, outline[i], outline[(i + 1) % outline.size()]);
  }
  triangles = std::move(out);
  return outOrigin;
}

}  // namespace ivshadow
