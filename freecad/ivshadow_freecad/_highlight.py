"""FreeCAD's highlight of faces drawn again for a group that traces: the overlay of one view
with shadows (_Highlight) and FreeCAD's highlight colours (highlight_colours)."""

import math

import FreeCAD as App
from pivy import coin

from ._documents import _selection_observer
from ._mesh import _material_of, _mesh_of
from ._scene import _NAMES, _address, _children
from ._settings import _colour_from_parameter


# -- FreeCAD's highlight of faces, for the tracer -------------------------------------------------
#
# FreeCAD draws the highlight of a face (selection green, pre-selection yellow) inside
# SoBrepFaceSet::GLRender: the face's triangles again, with the highlight colour as the emissive
# colour over the face's own lit material. A group that traces (renderer TRACER, or AUTO where GL
# is a software rasteriser) reads its triangles through Coin's SoCallbackAction and never runs
# that GLRender, so it showed no face highlight (edges and points, drawn by GL after the traced
# picture, kept theirs). The overlay below draws the highlighted faces into the group as shapes
# of their own, traced and shadowed like the faces: FreeCAD's own triangles of each face (the
# coordinates, normals and per-face triangle counts of the view provider's SoBrepFaceSet, so
# that the overlay covers the face exactly as drawn), the view provider's material with the
# highlight colour as emissive, a hair in front of the face along its normals (the tracer takes
# the nearest opaque surface, and coincident ones tie at random).

# FreeCAD's colours of pre-selection and selection, and its switches: parameters of the 3D view
# (User parameter:BaseApp/Preferences/View), whose defaults are those of FreeCAD's ViewParams
# (Gui/ViewParams.h: HighlightColor 0xe1e114ff, SelectionColor 0x1cad1cff), as 0xRRGGBBAA.
VIEW_PARAMETERS = "User parameter:BaseApp/Preferences/View"
_VIEW_DEFAULTS = {"HighlightColor": 0xE1E114FF, "SelectionColor": 0x1CAD1CFF}


def highlight_colours():
    """FreeCAD's (pre-selection, selection) colours, (r, g, b) in 0..1, from its parameters."""
    group = App.ParamGet(VIEW_PARAMETERS)
    return tuple(_colour_from_parameter(group.GetUnsigned(name, _VIEW_DEFAULTS[name]))
                 for name in ("HighlightColor", "SelectionColor"))


# The overlay's distance in front of the face, as a fraction of the model's size: far above the
# tracer's precision (its ray parameter runs from the near to the far plane in a float), far
# below a pixel at any zoom that shows the model.
_HIGHLIGHT_OFFSET = 1e-4


class _Highlight:
    """The overlay of one view with shadows: a separator in its group that holds, while the
    group traces, a shape for each highlighted face (or object), unpickable so that FreeCAD's
    picking still finds the face under it. Updated as FreeCAD's selection changes, and from a
    delay-queue sensor after an object is deleted (once FreeCAD has finished with it)."""

    def __init__(self, state):
        self.state = state
        self.root = coin.SoSeparator()
        self.root.setName(_NAMES["highlight"])
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        self.root.addChild(pick)
        # Shadowed like the face, casting nothing: the face itself casts the same shadow (a
        # transparent face's shadow would otherwise darken while it is highlighted).
        style = coin.SoType.fromName(coin.SbName("ShadowStyle")).createInstance()
        if style is not None and style.getField("style") is not None:
            style.getField("style").set("SHADOWED")
            self.root.addChild(style)
        self.pieces = coin.SoGroup()
        self.root.addChild(self.pieces)
        self.cache = {}  # key -> (token, node) of the pieces built
        self.sensor = coin.SoOneShotSensor(self._update_now, None)
        self.warned = False

    def schedule(self):
        if not self.sensor.isScheduled():
            self.sensor.schedule()

    def stop(self):
        self.sensor.unschedule()
        self.pieces.removeAllChildren()
        self.cache = {}

    def _update_now(self, data, sensor):
        self.update()

    def traces(self):
        """Whether the group may trace: the renderer is AUTO or TRACER. (With AUTO on a GPU the
        group draws with GL, FreeCAD's highlight with it; the overlay then draws the same colour
        over it.)"""
        return str(self.state.settings.get("renderer", "AUTO")).upper() != "RASTER"

    def wanted(self):
        """The highlights to draw: (object, subname, colour, order), selection first."""
        import FreeCADGui as Gui
        if not self.traces():
            return []
        document = self.state.document
        view = App.ParamGet(VIEW_PARAMETERS)
        preselection_colour, selection_colour = highlight_colours()
        wanted = []
        if view.GetBool("EnableSelection", True):
            for entry in Gui.Selection.getSelectionEx(document, 0):
                names = entry.SubElementNames or ("",)
                for sub in names:
                    wanted.append((entry.ObjectName, sub, selection_colour, 1))
        presel = _selection_observer.preselection
        if presel is not None and presel[0] == document and \
                view.GetBool("EnablePreselection", True):
            wanted.append((presel[1], presel[2], preselection_colour, 2))
        return wanted

    def update(self):
        try:
            self._update()
        except Exception:  # noqa: BLE001  (never an error inside FreeCAD's event handling)
            import traceback
            if not self.warned:
                self.warned = True
                App.Console.PrintWarning("ivshadow.freecad: the highlight overlay failed:\n%s"
                                         % traceback.format_exc())

    def _update(self):
        if self.state.document not in App.listDocuments():
            self.pieces.removeAllChildren()  # the document is closing
            return
        document = App.getDocument(self.state.document)
        bounds = self.state.bounds
        size = 1.0
        if bounds is not None:
            size = max(math.sqrt(sum((bounds[i + 3] - bounds[i]) ** 2 for i in range(3))), 1e-6)
        shown, nodes = [], []  # the pieces' keys and nodes, in drawing order
        for object_name, sub, colour, order in self.wanted():
            built = self._piece(document, object_name, sub, colour,
                                order * _HIGHLIGHT_OFFSET * size)
            if built is not None:
                key, node = built
                shown.append(key)
                nodes.append(node)
        self.cache = {key: self.cache[key] for key in shown if key in self.cache}
        addresses = [_address(node) for node in nodes]
        if addresses == _children(self.pieces):
            return  # nothing changed: the group reads nothing again
        self.pieces.removeAllChildren()
        for node in nodes:
            self.pieces.addChild(node)

    def _piece(self, document, object_name, sub, colour, offset):
        import FreeCADGui as Gui
        import numpy
        top = document.getObject(object_name)
        if top is None:
            return None
        path, _, element = sub.rpartition(".")
        path = path + "." if path else ""
        if element and not (element.startswith("Face") and element[4:].isdigit()):
            return None  # an edge or a point: GL draws their highlight after the picture
        face = int(element[4:]) - 1 if element else None
        target, accumulated = top, App.Matrix()
        if path:
            resolved = top.getSubObject(path, retType=1, matrix=App.Matrix())
            if not resolved or resolved[0] is None:
                return None
            target, accumulated = resolved
        else:
            accumulated = top.Placement.toMatrix() if hasattr(top, "Placement") else App.Matrix()
        gui_document = Gui.getDocument(target.Document.Name)
        view_object = gui_document.getObject(target.Name)
        if view_object is None or not view_object.Visibility:
            return None
        mesh = _mesh_of(target.Document.Name, target.Name)
        if mesh is None:
            return None
        # The view provider's root is drawn in its parent's coordinates: the accumulated
        # placement less the object's own (which the root's transform holds, in mesh.matrix).
        own = target.Placement.toMatrix() if hasattr(target, "Placement") else App.Matrix()
        parent = accumulated.multiply(own.inverse())
        parent = numpy.array(parent.A, dtype=float).reshape(4, 4).T  # as Coin's row vectors
        matrix = mesh.matrix.dot(parent)
        material = _material_of(view_object, face)
        token = (mesh.token[2:], tuple(matrix.flatten()), colour, material, offset)
        key = (target.Document.Name, target.Name, face, colour)
        cached = self.cache.get(key)
        if cached is not None and cached[0] == token:
            return key, cached[1]
        points, normals = mesh.triangles(face)
        if len(points) == 0:
            return None
        # In the mesh's own coordinates; the offset assumes no scale in the placement.
        moved = points + normals * offset
        node = coin.SoSeparator()
        transform = coin.SoMatrixTransform()
        transform.matrix.setValue(coin.SbMatrix(*[float(v) for v in matrix.flatten()]))
        node.addChild(transform)
        if mesh.hints is not None:
            hints = coin.SoShapeHints()
            hints.vertexOrdering, hints.shapeType, hints.faceType, hints.creaseAngle = mesh.hints
            node.addChild(hints)
        ambient, diffuse, specular, shininess, transparency = material
        look = coin.SoMaterial()
        look.ambientColor.setValue(coin.SbColor(*ambient))
        look.diffuseColor.setValues(0, len(diffuse), [list(c) for c in diffuse])
        look.specularColor.setValue(coin.SbColor(*specular))
        look.emissiveColor.setValue(coin.SbColor(*colour))
        look.shininess = shininess
        look.transparency = transparency
        node.addChild(look)
        binding = coin.SoMaterialBinding()
        triangles = len(points) // 3
        if len(diffuse) > 1 and face is None and len(diffuse) == len(mesh.counts):
            # One colour per face of the object (DiffuseColor): a colour per triangle.
            per_triangle = []
            for index, count in enumerate(mesh.counts):
                per_triangle.extend([list(diffuse[index])] * count)
            per_triangle = per_triangle[:triangles]
            look.diffuseColor.setValues(0, len(per_triangle), per_triangle)
            binding.value = coin.SoMaterialBinding.PER_FACE
        else:
            look.diffuseColor.setNum(1)
            binding.value = coin.SoMaterialBinding.OVERALL
        node.addChild(binding)
        coordinates = coin.SoCoordinate3()
        coordinates.point.setValues(0, len(moved), moved.tolist())
        node.addChild(coordinates)
        normal = coin.SoNormal()
        normal.vector.setValues(0, len(normals), normals.tolist())
        node.addChild(normal)
        normal_binding = coin.SoNormalBinding()
        normal_binding.value = coin.SoNormalBinding.PER_VERTEX
        node.addChild(normal_binding)
        faces = coin.SoFaceSet()
        faces.numVertices.setValues(0, triangles, [3] * triangles)
        node.addChild(faces)
        self.cache[key] = (token, node)
        return key, node
