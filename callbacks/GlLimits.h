#pragma once

namespace ivshadow {

// GL lights Coin uses (GL_LIGHT0..7), and so deep shadow map slots per group. shading.frag's
// kMaxLights must say the same.
inline constexpr int kMaxGlLights = 8;

// GL's integer state `name` (glGetIntegerv) in the current context.
int glInteger(unsigned int name);

// How a surface filters light in a deep shadow map; the values are deep_shadow_common.glsl's
// kColour* constants.
enum class ShadowColourModel : int { Monochrome = 0, Saturate = 1, Power = 2 };

}  // namespace ivshadow
