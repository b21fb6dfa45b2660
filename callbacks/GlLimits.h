#pragma once

namespace ivshadow {

// GL lights Coin uses (GL_LIGHT0..7), and so deep shadow map slots per group. shading.frag's
// kMaxLights must say the same.
inline constexpr int kMaxGlLights = 8;

// GL's integer state `name` (glGetIntegerv) in the current context.
int glInteger(unsigned int name);

}  // namespace ivshadow
