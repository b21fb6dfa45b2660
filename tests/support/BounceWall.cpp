#include "tests/support/BounceWall.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ivshadow::test {

std::vector<glm::dvec3> bounceWallFloor() {
  return {{0, -1, 0}, {2, -1, 0}, {2, 1, 0}, {0, 1, 0}};
}

double formFactor(const glm::dvec3& p, const glm::dvec3& n, const std::vector<glm::dvec3>& polygon) {
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec3 a = glm::normalize(polygon[i] - p);
    const glm::dvec3 b = glm::normalize(polygon[(i + 1) % polygon.size()] - p);
    const glm::dvec3 c = glm::cross(a, b);
    const double length = glm::length(c);
    if (length > 0.0)
      sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, c) / length;
  }
  return std::abs(sum) / (2.0 * std::acos(-1.0));
}

glm::dvec3 bounceWallPoint(int px, int py, int size) {
  const double down = std::acos(-1.0) / 12.0;  // 15 degrees
  const glm::dvec3 eye(2.897777, 0.0, 1.276457), right(0, 1, 0),
      up(-std::sin(down), 0.0, std::cos(down)), view(-std::cos(down), 0.0, -std::sin(down));
  const double across = (px + 0.5) / size * 2.4 - 1.2, height = 1.2 - (py + 0.5) / size * 2.4;
  const glm::dvec3 origin = eye + across * right + height * up;
  return origin + (-origin.x / view.x) * view;
}

bool inBounceWallPatch(const glm::dvec3& p) {
  return std::abs(p.y) <= 0.3 && p.z >= 0.3 && p.z <= 0.7;
}

}  // namespace ivshadow::test
