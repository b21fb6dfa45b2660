#pragma once

class SoNode;
class SoState;

namespace ivshadow {

// GL orders surfaces by a depth buffer of 24 bits, whose steps grow with the square of the
// distance over the near plane: past a far/near ratio of kMaxDepthRatio a perspective camera
// leaves them coarser than a part in a thousand of the view's depth at its far end, and GL
// (Coin, and RASTER) may draw surfaces in the wrong order where the tracer does not. Says so
// once per `where` when the camera in `state` is such a camera.
inline constexpr float kMaxDepthRatio = 1e5f;
void warnCoarseDepth(const SoNode* where, SoState* state);

}  // namespace ivshadow
