#include "raytrace/ShadowVolumes.h"

#include "raytrace/SurfaceOptics.h"
#include "scene/SceneTriangles.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>
#include <unordered_map>

namespace ivshadow {
namespace {

struct CornerKey {
  std::uint32_t bits[3];
  bool operator==(const CornerKey& o) const {
    return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
  }
};

struct CornerHash {
  std::size_t operator()(const CornerKey& k) const {
    std::size_t h = 1469598103934665603ull;
    for (std::uint32_t b : k.bits) h = (h ^ b) * 1099511628211ull;
    return h;
  }
};

CornerKey keyOf(const float position[3]) {
  CornerKey key;
  for (int i = 0; i < 3; ++i) {
    // -0 and +0 are one place.
    const float v = position[i] + 0.0f;
    std::memcpy(&key.bits[i], &v, sizeof(float));
  }
  return key;
}

// The mean texel of each image: what a volume, which has one colour, takes of a texture.
std::vector<glm::vec4> meanTexels(const std::vector<TextureImage>& textures) {
  std::vector<glm::vec4> means;
  for (const TextureImage& image : textures) {
    glm::dvec4 sum(0.0);
    const std::size_t texels = image.rgba.size() / 4;
    for (std::size_t i = 0; i < texels; ++i)
      for (int c = 0; c < 4; ++c) sum[c] += image.rgba[i * 4 + std::size_t(c)];
    means.push_back(texels == 0 ? glm::vec4(1.0f) : glm::vec4(sum / (255.0 * double(texels))));
  }
  return means;
}

}  // namespace

ShadowVolumes::ShadowVolumes(const SceneTriangles& casters, ShadowColourModel model) {
  const std::vector<glm::vec4> texels = meanTexels(casters.textures);
  std::unordered_map<CornerKey, std::uint32_t, CornerHash> welded;
  const auto corner = [&](const TriangleVertex& v) {
    const auto [it, added] = welded.try_emplace(keyOf(v.position), std::uint32_t(corners_.size()));
    if (added) {
      const glm::vec3 p(v.position[0], v.position[1], v.position[2]);
      low_ = corners_.empty() ? p : glm::min(low_, p);
      high_ = corners_.empty() ? p : glm::max(high_, p);
      corners_.push_back(p);
    }
    return it->second;
  };
  for (const TriangleBatch& batch : casters.batches) {
    const TextureImage* image =
        batch.texture >= 0 ? &casters.textures[std::size_t(batch.texture)] : nullptr;
    for (std::size_t v = batch.firstVertex; v + 2 < batch.firstVertex + batch.vertexCount; v += 3) {
      const TriangleVertex* t = &casters.vertices[v];
      glm::vec4 colour(0.0f);
      bool varies = false;
      for (int k = 0; k < 3; ++k) {
        const glm::vec4 c(t[k].colour[0], t[k].colour[1], t[k].colour[2], t[k].colour[3]);
        colour += c / 3.0f;
        varies = varies || std::memcmp(t[k].colour, t[0].colour, sizeof(t[0].colour)) != 0;
      }
      if (image != nullptr)
        colour = texturedColour(colour, texels[std::size_t(batch.texture)], image);
      if (varies || image != nullptr) ++approximated_;
      glm::vec3 through = isOpaque(colour.a) ? glm::vec3(0.0f) : transmittance(colour, model);
      // A clear triangle casts nothing: no volume.
      if (through == glm::vec3(1.0f)) continue;
      through = glm::max(through, glm::vec3(kMinTransmittance));
      weights_.emplace_back(std::log(through.x), std::log(through.y), std::log(through.z));
      for (int k = 0; k < 3; ++k) triangles_.push_back(corner(t[k]));
    }
  }

  buildEdges();
}

void ShadowVolumes::buildEdges() {
  edges_.clear();
  sides_.clear();
  // The edge table: every triangle's three edges, sorted so that the triangles on one edge
  // are neighbours.
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, int>> all;
  all.reserve(triangles_.size());
  for (std::uint32_t t = 0; t < weights_.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles_[t * 3 + std::uint32_t(k)];
      const std::uint32_t b = triangles_[t * 3 + std::uint32_t((k + 1) % 3)];
      if (a == b) continue;  // a degenerate triangle's collapsed edge bounds nothing
      all.emplace_back(std::min(a, b), std::max(a, b), t, a < b ? 1 : -1);
    }
  std::sort(all.begin(), all.end());
  sides_.reserve(all.size());
  for (std::size_t i = 0; i < all.size();) {
    Edge edge{std::get<0>(all[i]), std::get<1>(all[i]), std::uint32_t(sides_.size()), 0};
    for (; i < all.size() && std::get<0>(all[i]) == edge.from && std::get<1>(all[i]) == edge.to;
         ++i) {
      sides_.emplace_back(std::get<2>(all[i]), std::get<3>(all[i]));
      ++edge.sideCount;
    }
    edges_.push_back(edge);
  }
}

void ShadowVolumes::build(const glm::vec3& light, bool directional, const glm::vec3& low,
                          const glm::vec3& high, std::vector<VolumeVertex>& out) const {
  out.clear();
  const glm::vec3 boxLow = glm::min(low, low_), boxHigh = glm::max(high, high_);
  // A point light: past the box corner farthest from the light, kReach times. A directional
  // light: the far caps are the near ones moved along the light, so twice the box's diagonal
  // puts them past it whatever the direction.
  float reach = 2.0f * glm::length(boxHigh - boxLow);
  if (!directional) {
    float farthest = 0.0f;
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 corner(i & 1 ? boxHigh.x : boxLow.x, i & 2 ? boxHigh.y : boxLow.y,
                             i & 4 ? boxHigh.z : boxLow.z);
      farthest = std::max(farthest, glm::length(corner - light));
    }
    reach = kReach * farthest;
  }
  // Which way each triangle faces the light: +1 towards it, -1 away, 0 edge-on or degenerate
  // (no volume).
  std::vector<signed char> facing(weights_.size(), 0);
  const auto far = [&](const glm::vec3& p) {
    if (directional) return glm::vec4(p - light * reach, 1.0f);
    const glm::vec3 away = p - light;
    const float length = glm::length(away);
    // A corner at the light has no direction away from it; its volume has no area there.
    return glm::vec4(length > 0.0f ? light + away * (reach / length) : p, 1.0f);
  };
  const auto emit = [&](const glm::vec4& p, const glm::vec3& w) {
    out.push_back(VolumeVertex{{p.x, p.y, p.z, p.w}, {w.x, w.y, w.z, 0.0f}});
  };
  for (std::size_t t = 0; t < weights_.size(); ++t) {
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) p[k] = corners_[triangles_[t * 3 + std::size_t(k)]];
    const glm::vec3 normal = glm::cross(p[1] - p[0], p[2] - p[0]);
    // Corners in a row to float precision: a volume of no width, whose faces would only be
    // drawn for nothing (skipping it leaves every other volume closed).
    const float longest =
        std::max({glm::dot(p[1] - p[0], p[1] - p[0]), glm::dot(p[2] - p[1], p[2] - p[1]),
                  glm::dot(p[0] - p[2], p[0] - p[2])});
    if (glm::dot(normal, normal) <= 1e-12f * longest * longest) continue;
    const float towards = glm::dot(normal, directional ? light : light - p[0]);
    if (!(towards != 0.0f) || !std::isfinite(towards)) continue;
    facing[t] = towards > 0.0f ? 1 : -1;
    // Turned to face the light.
    if (facing[t] < 0) std::swap(p[1], p[2]);
    const glm::vec3& w = weights_[t];
    for (int k = 0; k < 3; ++k) emit(glm::vec4(p[k], 1.0f), w);
    emit(far(p[0]), w);
    emit(far(p[2]), w);
    emit(far(p[1]), w);
  }
  for (const Edge& edge : edges_) {
    glm::vec3 weight(0.0f);
    for (std::uint32_t s = edge.firstSide; s < edge.firstSide + edge.sideCount; ++s) {
      const auto [triangle, direction] = sides_[s];
      weight += float(direction * facing[triangle]) * weights_[triangle];
    }
    // Cancelled: an edge inside a surface of one colour, or between faces the light sees
    // from opposite sides with opposite windings.
    if (weight == glm::vec3(0.0f)) continue;
    const glm::vec3& u = corners_[edge.from];
    const glm::vec3& v = corners_[edge.to];
    const glm::vec4 uFar = far(u), vFar = far(v);
    emit(glm::vec4(u, 1.0f), weight);
    emit(uFar, weight);
    emit(vFar, weight);
    emit(glm::vec4(u, 1.0f), weight);
    emit(vFar, weight);
    emit(glm::vec4(v, 1.0f), weight);
  }
}

}  // namespace ivshadow
