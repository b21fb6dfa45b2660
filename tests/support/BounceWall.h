#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace ivshadow::test {

// The analytic answer for iv_scenes/bounce_wall.iv, computed from its geometry alone: the
// wall (x = 0) sees the floor (x 0 .. 2, y -1 .. 1, z = 0) lit straight down through the red
// pane, so its one-bounce light is kd_wall kd_floor T F, with T the pane's transmittance
// (SATURATE: (1 - a) clamp(1 - a + c) = (0.5, 0.25, 0.25)) and F the form factor from the wall
// point to the floor.
inline constexpr std::array<double, 3> kBounceWallTransmittance{0.5, 0.25, 0.25};
std::vector<glm::dvec3> bounceWallFloor();

// The form factor from a point with unit normal `n` to a polygon wholly in its upper
// half-space, by Lambert's contour integral: (1 / 2 pi) |sum over the edges of the angle they
// subtend times n . their plane's unit normal|.
double formFactor(const glm::dvec3& p, const glm::dvec3& n, const std::vector<glm::dvec3>& polygon);

// The wall point seen at pixel (px, py) of a size x size picture of bounce_wall.iv: its
// orthographic camera at (2.897777, 0, 1.276457), looking along (-cos 15, 0, -sin 15) degrees
// with +y to the right and (-sin 15, 0, cos 15) up, 2.4 units across; the pixel's ray meets
// the wall's plane x = 0.
glm::dvec3 bounceWallPoint(int px, int py, int size);

// Whether a wall point lies in the patch the tests check: 0.3 or more from the floor and
// the wall's edges, where the instant-radiosity clamp and the edge strata do not reach.
bool inBounceWallPatch(const glm::dvec3& p);

}  // namespace ivshadow::test
