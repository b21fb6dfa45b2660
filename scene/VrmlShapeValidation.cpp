#include "scene/VrmlShapeValidation.h"

#include "scene/IndexChecks.h"

#include <Inventor/VRMLnodes/SoVRMLColor.h>
#include <Inventor/VRMLnodes/SoVRMLCoordinate.h>
#include <Inventor/VRMLnodes/SoVRMLElevationGrid.h>
#include <Inventor/VRMLnodes/SoVRMLExtrusion.h>
#include <Inventor/VRMLnodes/SoVRMLIndexedFaceSet.h>
#include <Inventor/VRMLnodes/SoVRMLIndexedLineSet.h>
#include <Inventor/VRMLnodes/SoVRMLNormal.h>
#include <Inventor/VRMLnodes/SoVRMLPointSet.h>
#include <Inventor/VRMLnodes/SoVRMLTextureCoordinate.h>

namespace ivshadow {
namespace {

// How many values a shape's data node holds: -1 where it has none (Coin then generates
// normals or leaves colours to the material), the node's values otherwise. Coin casts the node
// to the type it expects without looking: another type is a defect of its own.
struct Values {
  long count = -1;
  std::string wrongType;
};

template <typename Node, typename Field>
Values valuesOf(const SoSFNode& field, const char* fieldName, Field Node::*values) {
  Values result;
  const SoNode* node = field.getValue();
  if (node == nullptr) return result;
  if (!node->isOfType(Node::getClassTypeId())) {
    result.wrongType = std::string(fieldName) + " holds a " +
                       node->getTypeId().getName().getString() + "; expected a " +
                       Node::getClassTypeId().getName().getString();
    return result;
  }
  result.count = (static_cast<const Node*>(node)->*values).getNum();
  return result;
}

// Values read per vertex or per face (polyline) through `indices` where given, otherwise
// through coordIndex (per vertex) or by the face's number (per face).
std::string boundValuesDefect(const SoMFInt32& coordIndex, const IndexRuns& runs, bool perVertex,
                              const char* perVertexName, bool indexed, const SoMFInt32& indices,
                              const char* indexName, long count, const char* what,
                              const char* unit) {
  if (perVertex) {
    if (indexed) return indicesPerVertex(coordIndex, indices, indexName, count, what);
    std::string defect = indicesInside(coordIndex, "coordIndex", count, what);
    return defect.empty() ? defect
                          : defect + " (coordIndex indexes them too: no " + indexName + ")";
  }
  if (indexed) return indicesPerUnit(indices, indexName, runs.runs, unit, count, what);
  return valuesPerUnit(what, (std::string(perVertexName) + " FALSE without " + indexName).c_str(),
                       unit, runs.runs, count);
}

// The coordinates an indexed VRML97 shape reads: its coord node's points, through coordIndex,
// in runs (faces, polylines) of at least `shortest` indices.
// (The face set and the line set declare the same fields on different bases.)
template <typename Set>
std::string coordinatesDefect(const Set* set, const IndexRuns& runs, long shortest,
                              const char* run) {
  const Values coords = valuesOf(set->coord, "coord", &SoVRMLCoordinate::point);
  if (!coords.wrongType.empty()) return coords.wrongType;
  if (coords.count < 0 && set->coordIndex.getNum() > 0)
    return "coordIndex indexes coordinates, but the shape has no coord node";
  if (std::string defect =
          indicesInside(set->coordIndex, "coordIndex", std::max(coords.count, 0L), "coordinates");
      !defect.empty())
    return defect;
  return shortRun(runs, shortest, run);
}

std::string faceSetDefect(const SoVRMLIndexedFaceSet* set) {
  const IndexRuns runs = IndexRuns::of(set->coordIndex);
  // generatePrimitives takes three indices of every face before looking at any.
  if (std::string defect = coordinatesDefect(set, runs, 3, "face"); !defect.empty()) return defect;

  const Values colours = valuesOf(set->color, "color", &SoVRMLColor::color);
  if (!colours.wrongType.empty()) return colours.wrongType;
  if (colours.count >= 0) {
    const bool perVertex = set->colorPerVertex.getValue();
    if (std::string defect = boundValuesDefect(set->coordIndex, runs, perVertex, "colorPerVertex",
                                               indexGiven(set->colorIndex), set->colorIndex,
                                               "colorIndex", colours.count, "colours", "face");
        !defect.empty())
      return defect;
    // Coin tessellates a non-convex face through a cache that reads texCoordIndex in place
    // of the colours' coordIndex (SoVRMLIndexedFaceSet, Coin 4.0).
    if (perVertex && !indexGiven(set->colorIndex) && !set->convex.getValue() && runs.longest > 3 &&
        indexGiven(set->texCoordIndex))
      if (std::string defect =
              indicesPerVertex(set->coordIndex, set->texCoordIndex, "texCoordIndex", colours.count,
                               "colours (Coin reads them through texCoordIndex "
                               "where a face of more than 3 vertices is not "
                               "convex)");
          !defect.empty())
        return defect;
  }
  const Values normals = valuesOf(set->normal, "normal", &SoVRMLNormal::vector);
  if (!normals.wrongType.empty()) return normals.wrongType;
  if (normals.count > 0)  // none: Coin generates them and ignores normalIndex
    if (std::string defect =
            boundValuesDefect(set->coordIndex, runs, set->normalPerVertex.getValue(),
                              "normalPerVertex", indexGiven(set->normalIndex), set->normalIndex,
                              "normalIndex", normals.count, "normals", "face");
        !defect.empty())
      return defect;
  const Values texture = valuesOf(set->texCoord, "texCoord", &SoVRMLTextureCoordinate::point);
  if (!texture.wrongType.empty()) return texture.wrongType;
  if (texture.count > 0)
    return boundValuesDefect(set->coordIndex, runs, true, "", indexGiven(set->texCoordIndex),
                             set->texCoordIndex, "texCoordIndex", texture.count,
                             "texture coordinates", "face");
  return {};
}

std::string lineSetDefect(const SoVRMLIndexedLineSet* set) {
  const IndexRuns runs = IndexRuns::of(set->coordIndex);
  if (std::string defect = coordinatesDefect(set, runs, 2, "polyline"); !defect.empty())
    return defect;
  const Values colours = valuesOf(set->color, "color", &SoVRMLColor::color);
  if (!colours.wrongType.empty()) return colours.wrongType;
  if (colours.count < 0) return {};
  // Unlike the face set, the line set reads colorIndex whenever it holds anything, a leading
  // -1 included.
  return boundValuesDefect(set->coordIndex, runs, set->colorPerVertex.getValue(), "colorPerVertex",
                           set->colorIndex.getNum() > 0, set->colorIndex, "colorIndex",
                           colours.count, "colours", "polyline");
}

std::string pointSetDefect(const SoVRMLPointSet* set) {
  const Values coords = valuesOf(set->coord, "coord", &SoVRMLCoordinate::point);
  if (!coords.wrongType.empty()) return coords.wrongType;
  const Values colours = valuesOf(set->color, "color", &SoVRMLColor::color);
  if (!colours.wrongType.empty()) return colours.wrongType;
  if (colours.count < 0) return {};
  return valuesPerUnit("colours", "a point set", "point", std::max(coords.count, 0L),
                       colours.count);
}

std::string elevationGridDefect(const SoVRMLElevationGrid* grid) {
  const long x = grid->xDimension.getValue(), z = grid->zDimension.getValue();
  if (x < 2 || z < 2) return {};  // Coin draws nothing
  const long vertices = x * z, quads = (x - 1) * (z - 1);
  if (std::string defect = valuesPerUnit("heights", "xDimension x zDimension", "vertex", vertices,
                                         grid->height.getNum());
      !defect.empty())
    return defect;
  const Values colours = valuesOf(grid->color, "color", &SoVRMLColor::color);
  if (!colours.wrongType.empty()) return colours.wrongType;
  // Coin's quad strips read a colour by the vertex's number even with colorPerVertex FALSE,
  // so a grid reads as many colours as vertices either way.
  if (colours.count >= 0)
    if (std::string defect =
            valuesPerUnit("colours",
                          "Coin's GL rendering of an elevation grid (by vertex, even with "
                          "colorPerVertex FALSE)",
                          "vertex", vertices, colours.count);
        !defect.empty())
      return defect;
  const Values normals = valuesOf(grid->normal, "normal", &SoVRMLNormal::vector);
  if (!normals.wrongType.empty()) return normals.wrongType;
  if (normals.count > 0) {
    const bool perVertex = grid->normalPerVertex.getValue();
    if (std::string defect = valuesPerUnit(
            "normals", perVertex ? "normalPerVertex TRUE" : "normalPerVertex FALSE",
            perVertex ? "vertex" : "quad", perVertex ? vertices : quads, normals.count);
        !defect.empty())
      return defect;
  }
  const Values texture = valuesOf(grid->texCoord, "texCoord", &SoVRMLTextureCoordinate::point);
  if (!texture.wrongType.empty()) return texture.wrongType;
  if (texture.count > 0)
    return valuesPerUnit("texture coordinates", "an elevation grid", "vertex", vertices,
                         texture.count);
  return {};
}

}  // namespace

std::string vrmlShapeDefect(const SoShape* shape) {
  if (shape->isOfType(SoVRMLIndexedFaceSet::getClassTypeId()))
    return faceSetDefect(static_cast<const SoVRMLIndexedFaceSet*>(shape));
  if (shape->isOfType(SoVRMLIndexedLineSet::getClassTypeId()))
    return lineSetDefect(static_cast<const SoVRMLIndexedLineSet*>(shape));
  if (shape->isOfType(SoVRMLPointSet::getClassTypeId()))
    return pointSetDefect(static_cast<const SoVRMLPointSet*>(shape));
  if (shape->isOfType(SoVRMLElevationGrid::getClassTypeId()))
    return elevationGridDefect(static_cast<const SoVRMLElevationGrid*>(shape));
  // A spine of one point is taken as closed and its second point read: the cross-section is
  // placed by whatever memory follows (a different picture on every run).
  if (shape->isOfType(SoVRMLExtrusion::getClassTypeId()) &&
      static_cast<const SoVRMLExtrusion*>(shape)->spine.getNum() == 1)
    return "spine holds 1 point; an extrusion needs at least 2";
  return {};
}

}  // namespace ivshadow
