#pragma once

#include <array>

namespace ivshadow {

struct ShadingLocations;

// How GL generates texture unit 0's coordinates s, t, r and q: a GL texgen mode per coordinate
// (GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP, GL_NORMAL_MAP, GL_REFLECTION_MAP), 0 where
// that coordinate is not generated. Coin's texture coordinate functions set these, and only
// the fixed-function pipeline applies them: the shading programs compute the coordinates
// from them (shading.vert, uTexGen).
using TexGenModes = std::array<int, 4>;

// The modes GL holds now for texture unit 0, whether or not generation is enabled: the caller
// knows from Coin's element that a function is in force. (Coin's element does not always
// enable generation again: after a pass that popped its state, the next traversal found the
// function's enables off and the element did not turn them on, measured with a peeled
// shape; the modes and planes, which Coin's callback sets every time, are current.)
TexGenModes currentTexGenModes();

// Sets `program`'s uTexGen.
void setTexGenModes(const ShadingLocations& program, const TexGenModes& modes);

}  // namespace ivshadow
