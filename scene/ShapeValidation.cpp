#include "scene/ShapeValidation.h"

#include "scene/CoinRef.h"
#include "scene/IndexChecks.h"
#include "scene/SceneTriangles.h"
#include "scene/VrmlShapeValidation.h"
#include "scene/WarnOnce.h"

#include <Inventor/SoPath.h>
#include <Inventor/elements/SoCoordinateElement.h>
#include <Inventor/elements/SoLazyElement.h>
#include <Inventor/elements/SoMaterialBindingElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoMultiTextureEnabledElement.h>
#include <Inventor/elements/SoNormalBindingElement.h>
#include <Inventor/elements/SoNormalElement.h>
#include <Inventor/elements/SoTextureCoordinateElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoIndexedLineSet.h>
#include <Inventor/nodes/SoIndexedNurbsCurve.h>
#include <Inventor/nodes/SoIndexedNurbsSurface.h>
#include <Inventor/nodes/SoIndexedShape.h>
#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoNonIndexedShape.h>
#include <Inventor/nodes/SoNurbsCurve.h>
#include <Inventor/nodes/SoNurbsSurface.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoQuadMesh.h>
#include <Inventor/nodes/SoTriangleStripSet.h>
#include <Inventor/nodes/SoVertexProperty.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>

namespace ivshadow {
namespace {

struct Counts {
  long coordinates = 0;
  long materials = 0;
  long normals = 0;
  long textureCoordinates = 0;
};

// What the shape will read: its own SoVertexProperty where that holds values, otherwise the
// elements in force.
Counts countsFor(SoCallbackAction* action, const SoVertexShape* shape) {
  SoState* state = action->getState();
  Counts counts;
  counts.coordinates = SoCoordinateElement::getInstance(state)->getNum();
  counts.materials = SoLazyElement::getInstance(state)->getNumDiffuse();
  counts.normals = SoNormalElement::getInstance(state)->getNum();
  counts.textureCoordinates = SoTextureCoordinateElement::getInstance(state)->getNum();
  if (const auto* property = static_cast<const SoVertexProperty*>(shape->vertexProperty.getValue());
      property != nullptr && property->isOfType(SoVertexProperty::getClassTypeId())) {
    if (property->vertex.getNum() > 0) counts.coordinates = property->vertex.getNum();
    if (property->orderedRGBA.getNum() > 0) counts.materials = property->orderedRGBA.getNum();
    if (property->normal.getNum() > 0) counts.normals = property->normal.getNum();
    if (property->texCoord.getNum() > 0) counts.textureCoordinates = property->texCoord.getNum();
  }
  return counts;
}

// The material binding the shape draws with: its own SoVertexProperty's where that holds
// colours, otherwise the element in force.
int materialBinding(SoState* state, const SoVertexShape* shape) {
  if (const auto* property = static_cast<const SoVertexProperty*>(shape->vertexProperty.getValue());
      property != nullptr && property->isOfType(SoVertexProperty::getClassTypeId()) &&
      property->orderedRGBA.getNum() > 0)
    return property->materialBinding.getValue();
  return SoMaterialBindingElement::get(state);
}

// The normal binding the shape draws with: its own SoVertexProperty's where that holds
// normals, otherwise the element in force.
int normalBinding(SoState* state, const SoVertexShape* shape) {
  if (const auto* property = static_cast<const SoVertexProperty*>(shape->vertexProperty.getValue());
      property != nullptr && property->isOfType(SoVertexProperty::getClassTypeId()) &&
      property->normal.getNum() > 0)
    return property->normalBinding.getValue();
  return SoNormalBindingElement::get(state);
}

std::string needMore(const std::string& what, long need, long start, long have) {
  return what + " asks for " + std::to_string(need) + " vertices from index " +
         std::to_string(start) + "; the coordinates hold " + std::to_string(have);
}

std::string nonIndexedDefect(const SoNonIndexedShape* shape, const Counts& counts) {
  const long start = shape->startIndex.getValue();
  if (start < 0) return "startIndex " + std::to_string(start) + " is negative";
  if (shape->isOfType(SoQuadMesh::getClassTypeId())) {
    const auto* mesh = static_cast<const SoQuadMesh*>(shape);
    const long rows = mesh->verticesPerColumn.getValue(), columns = mesh->verticesPerRow.getValue();
    if (rows < 0 || columns < 0)
      return "verticesPerRow " + std::to_string(columns) + " x verticesPerColumn " +
             std::to_string(rows) + " is negative";
    if (start + rows * columns > counts.coordinates)
      return needMore("verticesPerRow x verticesPerColumn", rows * columns, start,
                      counts.coordinates);
    return {};
  }
  if (shape->isOfType(SoPointSet::getClassTypeId())) {
    const long points = static_cast<const SoPointSet*>(shape)->numPoints.getValue();
    if (points < -1) return "numPoints " + std::to_string(points) + " is negative";
    if (points >= 0 && start + points > counts.coordinates)
      return needMore("numPoints", points, start, counts.coordinates);
    return {};
  }
  // FaceSet, LineSet, TriangleStripSet: one count per face, line or strip. Coin reads -1 as
  // "the rest of the coordinates" only as the one value (SoNonIndexedShape::
  // fixNumVerticesPointers), and a lone 0 as nothing to draw. Any other count below three
  // breaks its generatePrimitives (found by SceneReaderFuzzer: a FaceSet of two coordinates):
  // SoFaceSet's loop over a face of 0 vertices runs away and one of 1 or 2 reads its empty
  // normal cache; SoTriangleStripSet's default normals run away on a strip of fewer than 3.
  const auto* field = dynamic_cast<const SoMFInt32*>(shape->getField("numVertices"));
  if (field == nullptr) return {};
  const bool polygons = shape->isOfType(SoFaceSet::getClassTypeId()) ||
                        shape->isOfType(SoTriangleStripSet::getClassTypeId());
  const long minimum = polygons ? 3 : 0;
  const char* unit = shape->isOfType(SoFaceSet::getClassTypeId()) ? "a face" : "a strip";
  if (field->getNum() == 1 && (*field)[0] == 0) return {};
  if (field->getNum() == 1 && (*field)[0] == -1) {
    const long rest = counts.coordinates - start;
    if (counts.coordinates > 1 && rest < minimum)
      return "numVertices -1 leaves " + std::to_string(rest) + " vertices from index " +
             std::to_string(start) + "; " + unit + " needs at least 3";
    return {};
  }
  long total = 0;
  for (int i = 0; i < field->getNum(); ++i) {
    const long count = (*field)[i];
    if (count == -1)
      return "numVertices[" + std::to_string(i) +
             "] -1 (the rest of the coordinates) must be the only value";
    if (count < 0)
      return "numVertices[" + std::to_string(i) + "] " + std::to_string(count) + " is negative";
    if (count < minimum)
      return "numVertices[" + std::to_string(i) + "] " + std::to_string(count) + ": " + unit +
             " needs at least 3 vertices";
    total += count;
    if (start + total > counts.coordinates)
      return needMore("numVertices", total, start, counts.coordinates);
  }
  return {};
}

// What PER_PART and PER_FACE bind to on each of Inventor's indexed shapes, and how many of
// them its coordIndex holds (Coin 4.0's SoIndexedFaceSet, SoIndexedLineSet and
// SoIndexedTriangleStripSet); other indexed shapes are checked per index only.
struct Parts {
  const char* partUnit = nullptr;
  long parts = 0;
  const char* faceUnit = nullptr;
  long faces = 0;
};

Parts partsOf(const SoIndexedShape* shape, const IndexRuns& runs) {
  if (shape->isOfType(SoIndexedFaceSet::getClassTypeId()))
    return {"face", runs.runs, "face", runs.runs};
  if (shape->isOfType(SoIndexedLineSet::getClassTypeId()))
    return {"segment", runs.segments, "polyline", runs.runs};
  if (shape->isOfType(SoIndexedTriangleStripSet::getClassTypeId()))
    return {"strip", runs.runs, "triangle", runs.triangles};
  return {};
}

// What a binding names in messages: "materialBinding", "materialIndex", "materials".
struct Bound {
  const char* bindingField;
  const char* indexField;
  const char* what;
};
constexpr Bound kMaterials{"materialBinding", "materialIndex", "materials"};
constexpr Bound kNormals{"normalBinding", "normalIndex", "normals"};

const char* bindingName(int binding) {
  using B = SoMaterialBindingElement;  // SoNormalBindingElement's values are the same
  switch (binding) {
    case B::PER_PART:
      return "PER_PART";
    case B::PER_PART_INDEXED:
      return "PER_PART_INDEXED";
    case B::PER_FACE:
      return "PER_FACE";
    case B::PER_FACE_INDEXED:
      return "PER_FACE_INDEXED";
    case B::PER_VERTEX:
      return "PER_VERTEX";
    case B::PER_VERTEX_INDEXED:
      return "PER_VERTEX_INDEXED";
    default:
      return "OVERALL";
  }
}

// The `count` values (materials or normals) an indexed shape reads under `binding`: one per
// vertex, part or face, in order or through `indices` (coordIndex in their place for
// PER_VERTEX_INDEXED; for the other indexed bindings Coin's generatePrimitives or GL
// rendering dereferences null without them).
std::string boundDefect(const SoIndexedShape* shape, int binding, const IndexRuns& runs, long count,
                        const SoMFInt32& indices, const Bound& bound) {
  using B = SoMaterialBindingElement;
  const Parts parts = partsOf(shape, runs);
  const bool given = indexGiven(indices);
  const std::string named = std::string(bound.bindingField) + " " + bindingName(binding);
  switch (binding) {
    case B::PER_VERTEX:
      return valuesPerUnit(bound.what, named.c_str(), "vertex", runs.vertices, count);
    case B::PER_VERTEX_INDEXED:
      if (!given) {
        std::string defect = indicesInside(shape->coordIndex, "coordIndex", count, bound.what);
        return defect.empty() ? defect
                              : defect + " (" + named + " without a " + bound.indexField +
                                    " indexes the " + bound.what + " by coordIndex)";
      }
      return indicesPerVertex(shape->coordIndex, indices, bound.indexField, count, bound.what);
    case B::PER_PART:
    case B::PER_FACE: {
      const bool part = binding == B::PER_PART;
      const char* unit = part ? parts.partUnit : parts.faceUnit;
      if (unit == nullptr) return {};
      return valuesPerUnit(bound.what, named.c_str(), unit, part ? parts.parts : parts.faces,
                           count);
    }
    case B::PER_PART_INDEXED:
    case B::PER_FACE_INDEXED: {
      const bool part = binding == B::PER_PART_INDEXED;
      const char* unit = part ? parts.partUnit : parts.faceUnit;
      if (unit == nullptr)
        return given ? indicesInside(indices, bound.indexField, count, bound.what) : std::string();
      if (!given) return named + " without a " + bound.indexField + " (one index per " + unit + ")";
      return indicesPerUnit(indices, bound.indexField, part ? parts.parts : parts.faces, unit,
                            count, bound.what);
    }
    default:
      return {};
  }
}

std::string indexedDefect(SoCallbackAction* action, const SoIndexedShape* shape,
                          const Counts& counts) {
  if (std::string defect =
          indicesInside(shape->coordIndex, "coordIndex", counts.coordinates, "coordinates");
      !defect.empty())
    return defect;
  SoState* state = action->getState();
  const IndexRuns runs = IndexRuns::of(shape->coordIndex);
  // Coin's strips and polylines take their first three (two) indices before looking at any:
  // a shorter one reads coordinate -1 (SoIndexedTriangleStripSet, SoIndexedLineSet).
  const bool strips = shape->isOfType(SoIndexedTriangleStripSet::getClassTypeId());
  const bool lines = shape->isOfType(SoIndexedLineSet::getClassTypeId());
  if (std::string defect = shortRun(runs,
                                    strips  ? 3
                                    : lines ? 2
                                            : 0,
                                    strips ? "strip" : "polyline");
      !defect.empty())
    return defect;
  // Under PER_VERTEX Coin reads one material per vertex, in coordIndex order, whatever the
  // materials in force hold (SGI's indexedTriangleMesh.iv draws its mesh again under a single
  // BaseColor: the colours came from whatever memory followed it, different on each run).
  if (std::string defect = boundDefect(shape, materialBinding(state, shape), runs, counts.materials,
                                       shape->materialIndex, kMaterials);
      !defect.empty())
    return defect;
  // Normals in force are read as bound (without any, Coin generates its own and binds them
  // itself).
  if (counts.normals > 0)
    if (std::string defect = boundDefect(shape, normalBinding(state, shape), runs, counts.normals,
                                         shape->normalIndex, kNormals);
        !defect.empty())
      return defect;
  // Texture coordinates given are read per vertex, through textureCoordIndex or coordIndex.
  if (indexGiven(shape->textureCoordIndex) && counts.textureCoordinates > 0)
    if (std::string defect = indicesInside(shape->textureCoordIndex, "textureCoordIndex",
                                           counts.textureCoordinates, "texture coordinates");
        !defect.empty())
      return defect;
  return {};
}

// GLU's largest NURBS order (MAXORDER of SGI's NURBS library, which Debian's libGLU is).
constexpr long kMaxNurbsOrder = 24;

// A NURBS knot vector against its control point count: Coin takes the order as knots minus
// control points and reads the control points, the knots and (for normals, which it computes
// itself) order-sized arrays without checking any of it; GLU refuses an order outside
// 1..min(control points, 24) or decreasing knots, which Coin's normal code does not.
std::string knotDefect(const char* points, long controlPoints, const char* knots,
                       const SoMFFloat& vector) {
  if (controlPoints < 1)
    return std::string(points) + " " + std::to_string(controlPoints) + " is not positive";
  const long order = vector.getNum() - controlPoints;
  if (order < 1 || order > std::min(controlPoints, kMaxNurbsOrder))
    return std::string(knots) + " holds " + std::to_string(vector.getNum()) + " knots for " +
           std::to_string(controlPoints) + " control points: the order (knots minus control " +
           "points) must lie in 1.." + std::to_string(std::min(controlPoints, kMaxNurbsOrder));
  for (int i = 1; i < vector.getNum(); ++i)
    if (!(vector[i] >= vector[i - 1]))
      return std::string(knots) + "[" + std::to_string(i) + "] " + std::to_string(vector[i]) +
             " is less than the knot before it";
  return {};
}

// `need` control points read from the coordinates in force, or through `indices` (indexed
// shapes), which must then hold that many entries, each inside the coordinates.
std::string controlPointDefect(long need, long have, const SoMFInt32* indices, const char* name,
                               const char* what) {
  if (indices == nullptr) {
    if (need > have)
      return "the control points ask for " + std::to_string(need) + " " + what + "; there are " +
             std::to_string(have);
    return {};
  }
  if (indices->getNum() < need)
    return std::string(name) + " holds " + std::to_string(indices->getNum()) + " indices for " +
           std::to_string(need) + " control points";
  // Every index is a control point: -1 ends nothing here.
  for (int i = 0; i < indices->getNum(); ++i)
    if ((*indices)[i] < 0 || (*indices)[i] >= have)
      return std::string(name) + "[" + std::to_string(i) + "] " + std::to_string((*indices)[i]) +
             " is outside the " + std::to_string(have) + " " + what;
  return {};
}

std::string nurbsDefect(SoCallbackAction* action, const SoShape* shape) {
  SoState* state = action->getState();
  const long coordinates = SoCoordinateElement::getInstance(state)->getNum();
  const bool indexedSurface = shape->isOfType(SoIndexedNurbsSurface::getClassTypeId());
  if (shape->isOfType(SoNurbsSurface::getClassTypeId()) || indexedSurface) {
    // The two surface nodes have the same fields, each declared on its own class.
    const auto field = [shape](const char* name) { return shape->getField(name); };
    const auto count = [&](const char* name) {
      return long(static_cast<const SoSFInt32*>(field(name))->getValue());
    };
    const auto knots = [&](const char* name) -> const SoMFFloat& {
      return *static_cast<const SoMFFloat*>(field(name));
    };
    // Both directions' knots against their control points: (u, v), or the texture's (s, t).
    const auto directionsDefect = [&](const char* first, const char* firstKnots, const char* second,
                                      const char* secondKnots) {
      std::string defect = knotDefect(first, count(first), firstKnots, knots(firstKnots));
      return defect.empty() ? knotDefect(second, count(second), secondKnots, knots(secondKnots))
                            : defect;
    };
    const long u = count("numUControlPoints"), v = count("numVControlPoints");
    if (std::string defect = directionsDefect("numUControlPoints", "uKnotVector",
                                              "numVControlPoints", "vKnotVector");
        !defect.empty())
      return defect;
    const auto* coordIndex =
        indexedSurface ? static_cast<const SoMFInt32*>(field("coordIndex")) : nullptr;
    if (std::string defect =
            controlPointDefect(u * v, coordinates, coordIndex, "coordIndex", "coordinates");
        !defect.empty())
      return defect;
    // Texture control points are read only when all four fields are given, texture unit 0
    // is on (or the action keeps no such state) and the texture coordinates in force are
    // explicit ones (sogl_render_nurbs_surface).
    const long s = count("numSControlPoints"), t = count("numTControlPoints");
    const long textureCoordinates = SoTextureCoordinateElement::getInstance(state)->getNum();
    const bool textured =
        !state->isElementEnabled(SoMultiTextureEnabledElement::getClassStackIndex()) ||
        SoMultiTextureEnabledElement::get(state, 0);
    if (!textured || s == 0 || t == 0 || knots("sKnotVector").getNum() == 0 ||
        knots("tKnotVector").getNum() == 0 || textureCoordinates == 0)
      return {};
    if (std::string defect = directionsDefect("numSControlPoints", "sKnotVector",
                                              "numTControlPoints", "tKnotVector");
        !defect.empty())
      return defect;
    const auto* textureIndex =
        indexedSurface ? static_cast<const SoMFInt32*>(field("textureCoordIndex")) : nullptr;
    // Coin indexes them only when the first index is one (SoIndexedNurbsSurface).
    if (textureIndex != nullptr && (textureIndex->getNum() == 0 || (*textureIndex)[0] < 0))
      textureIndex = nullptr;
    return controlPointDefect(s * t, textureCoordinates, textureIndex, "textureCoordIndex",
                              "texture coordinates");
  }
  const bool indexedCurve = shape->isOfType(SoIndexedNurbsCurve::getClassTypeId());
  if (shape->isOfType(SoNurbsCurve::getClassTypeId()) || indexedCurve) {
    // The two curve nodes have the same fields, each declared on its own class.
    const long points =
        static_cast<const SoSFInt32*>(shape->getField("numControlPoints"))->getValue();
    const auto* knots = static_cast<const SoMFFloat*>(shape->getField("knotVector"));
    if (std::string defect = knotDefect("numControlPoints", points, "knotVector", *knots);
        !defect.empty())
      return defect;
    const auto* coordIndex =
        indexedCurve ? static_cast<const SoMFInt32*>(shape->getField("coordIndex")) : nullptr;
    return controlPointDefect(points, coordinates, coordIndex, "coordIndex", "coordinates");
  }
  return {};
}

// Where the shape lies in world coordinates, checked once its data is known to be sound (its
// bounding box reads all of it): farther than kLargestTracedCoordinate from the origin, or
// not finite (a MatrixTransform whose w is 0, coordinates of 1e30 times a scale).
std::string rangeDefect(SoCallbackAction* action, const SoShape* shape) {
  SbBox3f box;
  SbVec3f center;
  const_cast<SoShape*>(shape)->computeBBox(action, box, center);
  if (box.isEmpty()) return {};
  box.transform(SoModelMatrixElement::get(action->getState()));
  float farthest = 0.0f;
  for (const SbVec3f& corner : {box.getMin(), box.getMax()})
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(corner[i]))
        return "its transformation takes it to infinity (a matrix whose w is 0?)";
      farthest = std::max(farthest, std::fabs(corner[i]));
    }
  if (farthest <= kLargestTracedCoordinate) return {};
  std::ostringstream text;
  text << "it reaches " << farthest << " from the origin; rays are traced within "
       << kLargestTracedCoordinate;
  return text.str();
}

std::string dataDefect(SoCallbackAction* action, const SoShape* shape) {
  if (!shape->isOfType(SoVertexShape::getClassTypeId())) {
    std::string defect = vrmlShapeDefect(shape);
    return defect.empty() ? nurbsDefect(action, shape) : defect;
  }
  const Counts counts = countsFor(action, static_cast<const SoVertexShape*>(shape));
  if (shape->isOfType(SoNonIndexedShape::getClassTypeId()))
    return nonIndexedDefect(static_cast<const SoNonIndexedShape*>(shape), counts);
  if (shape->isOfType(SoIndexedShape::getClassTypeId()))
    return indexedDefect(action, static_cast<const SoIndexedShape*>(shape), counts);
  return {};
}

}  // namespace

std::string shapeDefect(SoCallbackAction* action, const SoShape* shape) {
  std::string defect = dataDefect(action, shape);
  return defect.empty() ? rangeDefect(action, shape) : defect;
}

SoCallbackAction::Response skipDefectiveShape(void*, SoCallbackAction* action, const SoNode* node) {
  const std::string defect = shapeDefect(action, static_cast<const SoShape*>(node));
  if (defect.empty()) return SoCallbackAction::CONTINUE;
  // Casters are extracted again whenever the scene changes, and by every renderer in the
  // process: the warning is said once per shape.
  if (firstWarning(node, "defective shape"))
    SoDebugError::postWarning("ivshadow",
                              "%s: %s; the shape casts no shadow and the reference "
                              "does not draw it",
                              describeNode(node).c_str(), defect.c_str());
  return SoCallbackAction::PRUNE;
}

std::vector<std::string> removeDefectiveShapes(SoNode* root, const std::string& file) {
  // Per defective shape found: the node drawn (the shape, or for a VRML97 geometry its
  // VRMLShape, where Coin's path ends), its parent, the shape and its defect, all held (paths
  // would be truncated, and the nodes freed, by the first removal).
  struct Defective {
    CoinRef<SoNode> drawn;
    CoinRef<SoNode> parent;
    int child = -1;  // drawn's index in parent
    CoinRef<SoNode> shape;
    std::string defect;
  };
  std::vector<Defective> found;
  SoCallbackAction action;
  // No primitive callbacks are registered, so Coin generates no primitives while looking.
  action.addPreCallback(
      SoShape::getClassTypeId(),
      [](void* data, SoCallbackAction* action, const SoNode* node) {
        std::string defect = shapeDefect(action, static_cast<const SoShape*>(node));
        if (!defect.empty()) {
          const SoPath* path = action->getCurPath();
          SoNode* parent = path->getLength() >= 2 ? path->getNodeFromTail(1) : nullptr;
          static_cast<std::vector<Defective>*>(data)->push_back(
              {CoinRef<SoNode>(path->getTail()), CoinRef<SoNode>(parent), path->getIndexFromTail(0),
               CoinRef<SoNode>(const_cast<SoNode*>(node)), std::move(defect)});
        }
        return SoCallbackAction::CONTINUE;
      },
      &found);
  action.apply(root);

  std::vector<std::string> warnings;
  // Latest first, so that the child indices found earlier stay valid. A shape under a group
  // that is used twice is found once per path at the same child of the same parent: removed
  // the first time, its place then holds a sibling, which stays. A shape used twice in one
  // group, valid in one place only, is removed only where it is defective. Each is named once.
  std::set<const SoNode*> named;
  for (auto it = found.rbegin(); it != found.rend(); ++it) {
    const Defective& defective = *it;
    std::string line =
        file + ": warning: " + describeNode(defective.shape.get()) + ": " + defective.defect;
    SoNode* parent = defective.parent.get();
    if (parent != nullptr && parent->isOfType(SoGroup::getClassTypeId())) {
      auto* group = static_cast<SoGroup*>(parent);
      if (defective.child < group->getNumChildren() &&
          group->getChild(defective.child) == defective.drawn.get())
        group->removeChild(defective.child);
      line += "; the shape is left out";
    } else {
      line += "; it casts no shadow";
    }
    if (named.insert(defective.shape.get()).second) warnings.insert(warnings.begin(), line);
  }
  return warnings;
}

}  // namespace ivshadow
