#pragma once

#include "ivshadow/Export.h"

#include <Inventor/actions/SoCallbackAction.h>

#include <string>
#include <vector>

class SoShape;

namespace ivshadow {

// The farthest from the origin a coordinate may lie and still be traced: Embree takes rays and
// triangles only within about 1.844e18 (FLT_LARGE, its ray.valid() assertion aborted the
// process for a visible surface at 1.8e18).
inline constexpr float kLargestTracedCoordinate = 1.8e18f;

// What is wrong with `shape`'s vertex data in the traversal state of `action`, or an empty
// string when nothing is:
// - counts that ask for more vertices than the coordinates in force hold (FaceSet, LineSet,
//   TriangleStripSet, QuadMesh, PointSet: startIndex, numVertices, verticesPerRow x
//   verticesPerColumn, numPoints), negative counts, a -1 in numVertices beside other values,
//   and faces or strips of fewer than three vertices;
// - indices past the end of the coordinates, or of the materials, normals and texture
//   coordinates they index (coordIndex, materialIndex, normalIndex, textureCoordIndex of
//   indexed shapes);
// - NURBS surfaces and curves (indexed or not) whose knot vectors do not fit their control
//   points (an order, knots minus control points, outside 1..min(control points, 24), or
//   decreasing knots), whose control points ask for more coordinates (or indices) than there
//   are, or whose texture control points ask for more texture coordinates.
// - VRML97 shapes whose indices or counts run past their data (scene/VrmlShapeValidation.h);
// - shapes that reach farther than kLargestTracedCoordinate from the origin, or whose
//   transformation takes them to infinity.
// Coin's own GL rendering checks some of these and warns; its generatePrimitives, which
// SoCallbackAction runs, reads whatever memory the counts name, so these checks come first.
IVSHADOW_INTERNAL std::string shapeDefect(SoCallbackAction* action, const SoShape* shape);

// A pre-callback for SoShape (any user data): prunes a shape with a defect, so that no
// triangle of it is generated, after one warning per shape and process naming it and the
// defect ("FaceSet 'Wall': numVertices asks for 7 vertices from index 0; the coordinates hold
// 3"), and continues with every other shape.
IVSHADOW_INTERNAL SoCallbackAction::Response skipDefectiveShape(void* data,
                                                                SoCallbackAction* action,
                                                                const SoNode* node);

// Removes from `root` every shape with a defect, in each place where it has one, so that no
// renderer, Coin's included, reads past its data (Coin's GL rendering checks some of these
// counts and not others: a TriangleStripSet asking for 100,000 vertices of three hangs it).
// Returns one line per removed shape for `file`: "FILE: warning: FaceSet 'Wall': ...; left out".
IVSHADOW_INTERNAL std::vector<std::string> removeDefectiveShapes(SoNode* root,
                                                                 const std::string& file);

}  // namespace ivshadow
