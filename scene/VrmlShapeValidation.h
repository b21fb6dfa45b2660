#pragma once

#include "ivshadow/Export.h"

#include <string>

class SoShape;

namespace ivshadow {

// What is wrong with a VRML97 shape's data, or an empty string when nothing is (or `shape` is
// not one of the VRML97 shapes checked here):
// - VRMLIndexedFaceSet, VRMLIndexedLineSet: coordIndex past the coord node's points, faces of
//   fewer than three and polylines of fewer than two indices; colours, normals and texture
//   coordinates read through colorIndex, normalIndex, texCoordIndex, or through coordIndex or
//   the face's number where those are absent, past their nodes' values;
// - VRMLPointSet: fewer colours than points;
// - VRMLElevationGrid: fewer heights, colours, normals or texture coordinates than the grid
//   reads, negative dimensions;
// - VRMLExtrusion: a spine of one point.
// The rules are what Coin 4.0's generatePrimitives, computeBBox and GL rendering read, none of
// which checks it (a bad colorIndex reads through SoCallbackAction::getMaterial); they read
// each VRML97 shape's own coord, color, normal and texCoord nodes, not the traversal state.
IVSHADOW_INTERNAL std::string vrmlShapeDefect(const SoShape* shape);

}  // namespace ivshadow
