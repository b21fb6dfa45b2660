"""FreeCAD's triangles of a view provider's faces (_Mesh, read by _mesh_of and cached in
_meshes) and the material it draws them with (_material_of): what the highlight overlay
(_highlight.py) draws a highlighted face with."""

from pivy import coin

from ._scene import _address

# The meshes of view providers, by (document, object): what the overlay takes of FreeCAD's
# triangles, read once per object and kept while its coordinates node is unchanged (a recompute
# or a change of the shape sets new coordinates, and a node's id changes with every change of
# its fields), so that moving the mouse over faces (pre-selection) reads nothing again.
_meshes = {}


def _drop_meshes(document, name=None):
    for key in [key for key in _meshes
                if key[0] == document and (name is None or key[1] == name)]:
        del _meshes[key]


class _Mesh:
    """FreeCAD's triangles of one view provider: its SoBrepFaceSet, the SoCoordinate3 and
    SoNormal it is drawn with, in the view provider's root's coordinates (`matrix`)."""

    def __init__(self, token, points, normals, coord_index, starts, counts, matrix, hints):
        self.token = token
        self.points = points
        self.normals = normals
        self.coord_index = coord_index
        self.starts = starts
        self.counts = counts
        self.matrix = matrix
        self.hints = hints
        self.faces = {}  # face index (or None: all) -> (points, normals) of its triangles

    def triangles(self, face):
        """The points and normals (n x 3 arrays, three rows a triangle) of face `face` (0-based;
        None: every face)."""
        import numpy
        if face not in self.faces:
            if face is None:
                indices = self.coord_index
            elif 0 <= face < len(self.counts):
                start = self.starts[face]
                indices = self.coord_index[start:start + 4 * self.counts[face]]
            else:
                indices = numpy.zeros(0, dtype=int)
            indices = indices[: len(indices) // 4 * 4].reshape(-1, 4)[:, :3].reshape(-1)
            indices = indices[(indices >= 0) & (indices < len(self.points))]
            indices = indices[: len(indices) // 3 * 3]
            points = self.points[indices]
            if self.normals is not None:
                normals = self.normals[indices]
            else:  # the triangles' own normals, as Coin would make them
                corners = points.reshape(-1, 3, 3)
                cross = numpy.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
                normals = numpy.repeat(cross, 3, axis=0)
            length = numpy.linalg.norm(normals, axis=1)
            normals = normals / numpy.where(length > 0, length, 1.0)[:, None]
            self.faces[face] = (points, normals)
        return self.faces[face]


def _mesh_of(document_name, object_name):
    """The _Mesh of an object's view provider (cached), or None where it draws no faces (a
    display mode without them, an object that is not a shape)."""
    import FreeCADGui as Gui
    import numpy
    view_object = Gui.getDocument(document_name).getObject(object_name)
    root = getattr(view_object, "RootNode", None) if view_object else None
    if root is None:
        return None
    # Each action lives as long as the paths it found are used: a path belongs to its action,
    # which frees it when it goes (pivy does not hold it), and a dangling path crashed FreeCAD.
    face_search = coin.SoSearchAction()  # the display mode shown (a switch's chosen child)
    face_search.setType(coin.SoType.fromName(coin.SbName("SoBrepFaceSet")))
    face_search.setInterest(coin.SoSearchAction.FIRST)
    face_search.apply(root)
    path = face_search.getPath()
    if path is None:
        return None
    face_set = path.getTail()
    # The coordinates it is drawn with: the last SoCoordinate3 traversed before it, a child of
    # one of the nodes along its path.
    along = {_address(path.getNode(i)): i for i in range(path.getLength())}
    coordinates = None
    coordinate_search = coin.SoSearchAction()
    coordinate_search.setType(coin.SoCoordinate3.getClassTypeId())
    coordinate_search.setInterest(coin.SoSearchAction.ALL)
    coordinate_search.apply(root)
    found = coordinate_search.getPaths()
    for i in range(found.getLength()):
        candidate = found[i]
        if candidate.getLength() >= 2 and _address(candidate.getNodeFromTail(1)) in along:
            coordinates = candidate.getTail()
    if coordinates is None:
        return None
    parent = path.getNodeFromTail(1)
    normal = hints = None
    for i in range(parent.getNumChildren()):
        child = parent.getChild(i)
        if child.isOfType(coin.SoNormal.getClassTypeId()):
            normal = child
        elif child.isOfType(coin.SoShapeHints.getClassTypeId()):
            hints = child
    token = (_address(face_set), face_set.getNodeId(), _address(coordinates),
             coordinates.getNodeId(), _address(normal) if normal else 0,
             normal.getNodeId() if normal else 0)
    key = (document_name, object_name)
    mesh = _meshes.get(key)
    matrix_action = coin.SoGetMatrixAction(coin.SbViewportRegion())
    matrix_action.apply(path)
    matrix = numpy.array([list(row) for row in matrix_action.getMatrix().getValue()])
    if mesh is not None and mesh.token[2:] == token[2:] and \
            mesh.coord_index.shape[0] == face_set.coordIndex.getNum():
        mesh.matrix = matrix  # the placement may have moved; the triangles are the same
        return mesh
    points = numpy.array([p.getValue() for p in coordinates.point.getValues(0)], dtype=float)
    normals = None
    if normal is not None and normal.vector.getNum() == len(points):
        normals = numpy.array([n.getValue() for n in normal.vector.getValues(0)], dtype=float)
    coord_index = numpy.array(face_set.coordIndex.getValues(0), dtype=int)
    part_index = face_set.getField("partIndex")
    counts = [int(c) for c in part_index.getValues(0)] if part_index is not None else []
    starts, start = [], 0
    for count in counts:
        starts.append(start)
        start += 4 * count
    hints_values = None
    if hints is not None:
        hints_values = (hints.vertexOrdering.getValue(), hints.shapeType.getValue(),
                        hints.faceType.getValue(), hints.creaseAngle.getValue())
    mesh = _Mesh(token, points, normals, coord_index, starts, counts, matrix, hints_values)
    _meshes[key] = mesh
    return mesh


def _material_of(view_object, faces):
    """The view provider's material as FreeCAD draws the face (`faces`: its index, or None for
    all): (ambient, diffuse list, specular, shininess, transparency)."""
    def rgb(colour):
        return tuple(float(c) for c in tuple(colour)[:3])
    ambient, specular, shininess = (0.2, 0.2, 0.2), (0.0, 0.0, 0.0), 0.2
    diffuse = [(0.8, 0.8, 0.8)]
    transparency = 0.0
    try:
        material = view_object.ShapeMaterial
        ambient, specular = rgb(material.AmbientColor), rgb(material.SpecularColor)
        shininess = float(material.Shininess)
        diffuse = [rgb(view_object.ShapeColor)]
        transparency = float(view_object.Transparency) / 100.0
        per_face = [rgb(colour) for colour in view_object.DiffuseColor]
        if len(per_face) > 1:
            if faces is None:
                diffuse = per_face
            elif faces < len(per_face):
                diffuse = [per_face[faces]]
    except Exception:  # noqa: BLE001  (a view provider without a shape's material)
        pass
    return ambient, diffuse, specular, shininess, transparency
