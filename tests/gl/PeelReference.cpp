#include "tests/gl/PeelReference.h"

#include <algorithm>
#include <cmath>

namespace ivshadow::test {
namespace {

// Coin sends colours as 8-bit values.
double quantise(double value) {
  return std::round(std::clamp(value, 0.0, 1.0) * 255.0) / 255.0;
}

}  // namespace

PeelReference::PeelReference(SoNode* root, double viewHeight, int size)
    : triangles_(extractShadowCasters(root)), viewHeight_(viewHeight), size_(size) {}

std::vector<PeelReference::Hit> PeelReference::hits(double x, double y) const {
  std::vector<Hit> out;
  const auto& v = triangles_.vertices;
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
    const TextureImage* texture = nullptr;
    for (const TriangleBatch& batch : triangles_.batches)
      if (i >= batch.firstVertex && i < batch.firstVertex + batch.vertexCount && batch.texture >= 0)
        texture = &triangles_.textures[std::size_t(batch.texture)];
    const TriangleVertex &a = v[i], &b = v[i + 1], &c = v[i + 2];
    const double ax = a.position[0], ay = a.position[1], bx = b.position[0], by = b.position[1],
                 cx = c.position[0], cy = c.position[1];
    const double area = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
    if (std::abs(area) < 1e-14) continue;  // seen edge-on: no pixel centre is covered
    const double wa = ((bx - x) * (cy - y) - (cx - x) * (by - y)) / area;
    const double wb = ((cx - x) * (ay - y) - (ax - x) * (cy - y)) / area;
    const double wc = 1.0 - wa - wb;
    if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
    Hit hit;
    hit.depth = -(wa * a.position[2] + wb * b.position[2] + wc * c.position[2]);
    for (int k = 0; k < 4; ++k)
      hit.colour[std::size_t(k)] =
          wa * quantise(a.colour[k]) + wb * quantise(b.colour[k]) + wc * quantise(c.colour[k]);
    if (texture != nullptr) {
      // MODULATE with nearest sampling (the test scenes set textureQuality 0.1), repeating.
      const double s = wa * a.texCoord[0] + wb * b.texCoord[0] + wc * c.texCoord[0];
      const double t = wa * a.texCoord[1] + wb * b.texCoord[1] + wc * c.texCoord[1];
      const int w = texture->width, h = texture->height;
      const int tx = ((int(std::floor(s * w)) % w) + w) % w;
      const int ty = ((int(std::floor(t * h)) % h) + h) % h;
      const unsigned char* texel =
          &texture->rgba[(std::size_t(ty) * std::size_t(w) + std::size_t(tx)) * 4];
      for (int k = 0; k < 4; ++k) hit.colour[std::size_t(k)] *= texel[k] / 255.0;
    }
    out.push_back(hit);
  }
  std::sort(out.begin(), out.end(), [](const Hit& p, const Hit& q) { return p.depth < q.depth; });
  return out;
}

std::array<double, 3> PeelReference::composite(std::vector<Hit> all, Keep keep) const {
  // Transparent layers in front of the first opaque hit; that hit ends the ray.
  std::vector<Hit> layers;
  std::optional<Hit> opaque;
  for (const Hit& hit : all) {
    if (hit.colour[3] >= 1.0 - 0.5 / 255.0) {
      opaque = hit;
      break;
    }
    if (hit.colour[3] > 0.0) layers.push_back(hit);
  }
  const int n = int(layers.size());
  std::array<double, 3> colour{0.0, 0.0, 0.0};
  double transmittance = 1.0;
  for (int i = 0; i < n; ++i) {
    if (i >= keep.front && i < n - keep.back) continue;
    const Hit& layer = layers[std::size_t(i)];
    for (int k = 0; k < 3; ++k)
      colour[std::size_t(k)] += transmittance * layer.colour[3] * layer.colour[std::size_t(k)];
    transmittance *= 1.0 - layer.colour[3];
  }
  if (opaque)
    for (int k = 0; k < 3; ++k)
      colour[std::size_t(k)] += transmittance * opaque->colour[std::size_t(k)];
  for (double& c : colour) c *= 255.0;
  return colour;
}

std::optional<std::array<double, 3>> PeelReference::pixel(int px, int py, Keep keep) const {
  const double unit = viewHeight_ / size_;
  const double x = -viewHeight_ / 2 + (px + 0.5) * unit;
  const double y = viewHeight_ / 2 - (py + 0.5) * unit;
  const std::array<double, 3> centre = composite(hits(x, y), keep);
  const double nudge = 0.02 * unit;
  for (const auto& [dx, dy] : {std::pair{nudge, 0.0}, {-nudge, 0.0}, {0.0, nudge}, {0.0, -nudge}}) {
    const std::array<double, 3> near = composite(hits(x + dx, y + dy), keep);
    for (int k = 0; k < 3; ++k)
      if (std::abs(near[std::size_t(k)] - centre[std::size_t(k)]) > 1.0) return std::nullopt;
  }
  return centre;
}

int PeelReference::depthComplexity() const {
  int most = 0;
  const double unit = viewHeight_ / size_;
  for (int py = 0; py < size_; ++py)
    for (int px = 0; px < size_; ++px) {
      int count = 0;
      for (const Hit& hit :
           hits(-viewHeight_ / 2 + (px + 0.5) * unit, viewHeight_ / 2 - (py + 0.5) * unit)) {
        if (hit.colour[3] >= 1.0 - 0.5 / 255.0) break;
        ++count;
      }
      most = std::max(most, count);
    }
  return most;
}

}  // namespace ivshadow::test
