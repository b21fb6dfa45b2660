#pragma once

#include <Inventor/SbColor.h>

#include <string>

class SoNode;

namespace ivshadow {

struct ReferenceResult;

// Completes a reference picture with what the trace does not draw: lines, points, text,
// markers and images, drawn by GL as Coin lays them out, over the traced picture and
// depth-tested against its surfaces, exactly as `renderer TRACER` draws them. `root` is the
// scene the reference traced; `background` its background. The pixels GL changed take GL's
// 8-bit colour; the others keep the trace's floats. Empty when drawn (or nothing was left to
// draw); else why not, and the picture stays the trace's. The traced picture and its depth
// are released either way.
std::string drawUntracedOver(SoNode* root, const SbColor& background, ReferenceResult& result);

}  // namespace ivshadow
