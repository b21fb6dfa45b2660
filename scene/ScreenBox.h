#pragma once

#include "ivshadow/Export.h"

#include <array>

class SbBox3f;
class SbMatrix;

namespace ivshadow {

// The pixels of a viewport that a box in the world may cover, seen through `viewing` (world
// to eye) and `projection` (eye to clip), as Coin's matrices multiply row vectors: its eight
// corners projected, the rectangle around them widened by `margin` pixels on each side and
// clipped to the viewport. Pixels outside it see nothing of the box. Relative to the
// viewport's corner, {x0, y0, x1, y1} with x1 and y1 one past the last pixel, rows bottom to
// top as GL's; empty (x0 == x1 or y0 == y1) when the box is empty or wholly outside the view
// volume's sides; the whole viewport when a corner lies on or behind the eye's plane, where
// the projection does not bound it.
IVSHADOW_INTERNAL std::array<int, 4> screenBox(const SbBox3f& box, const SbMatrix& viewing,
                                               const SbMatrix& projection, int width, int height,
                                               int margin);

}  // namespace ivshadow
