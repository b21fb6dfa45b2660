#pragma once

namespace ivshadow {

// Coin turns a GL light off when the separator it was traversed in ends (SoGLLightIdElement's
// pop: glDisable), and leaves its colours. The group's shading program adds up GL lights by
// number and cannot see which are on, so a light in a separator lit the shapes after the
// separator under RASTER, where Coin, TRACER and the reference do not. Coin's light-number
// element is made, from here on, as one whose pop also darkens the lights it turns off:
// nothing changes for fixed-function GL (they are off) and Coin sets every parameter of a light
// again when it turns it on. Once.
void registerLightScopeElement();

}  // namespace ivshadow
