#pragma once

class SoNode;
class SoState;

namespace ivshadow {

// GL orders surfaces by a depth buffer of 24 bits. A perspective camera's steps grow with the
// square of the distance over the near plane: past a far/near ratio of kMaxDepthRatio they are
// coarser than a part in a thousand of the view's depth at its far end. An orthographic
// camera's are even: past kMaxOrthographicDepthStep of the view's width a step spans features
// a pixel apart. GL (Coin, and RASTER) may then draw surfaces in the wrong order where the
// tracer does not. Says so once per `where` when the camera in `state` is such a camera.
inline constexpr float kMaxDepthRatio = 1e5f;
inline constexpr float kMaxOrthographicDepthStep = 1e-3f;
void warnCoarseDepth(const SoNode* where, SoState* state);

}  // namespace ivshadow
