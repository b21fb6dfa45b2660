"""Transparent, coloured shadows in FreeCAD's 3D view (docs/FREECAD.md).

    import ivshadow.freecad as shadows
    shadows.enable()                  # the active 3D view, with the preferences' settings
    shadows.enable(light_direction=(0.3, 0.5, -1), ground=False, renderer="RASTER")
    shadows.is_enabled()              # True
    shadows.disable()                 # FreeCAD's own picture again

enable() puts the view's model into a TransparentShadowGroup lit by one
DeepShadowDirectionalLight, with an automatic ground under it, and turns FreeCAD's headlight
(and backlight) off for the model, so that the shadows are as dark as the light makes them.

Where the group goes, and why. FreeCAD draws a document from its SoFCUnifiedSelection node
(`view.getSceneGraph()`): every view provider's root is a child of it, and both the live view
and `saveImage` (which builds a scene of its own around that node, with FreeCAD's headlight and
camera) draw it. A group put above it, in the render manager's scene, would shadow the live view
but not `saveImage`; so the group goes inside it and the view providers' roots move into the
group. FreeCAD appends the root of an object created later to the SoFCUnifiedSelection node: a
node sensor on it moves the newcomer into the group before the next redraw (the redraw sensor
has a lower priority). FreeCAD removes a deleted object's root from the SoFCUnifiedSelection
node only if it is a direct child (View3DInventorViewer::removeViewProvider looks it up with
findChild and does nothing when it is not there), so a Gui document observer removes it from
the group. FreeCAD's own nodes there (its event callback, the dimensions, the "on top"
selection group, the editing root of the sketcher and the transform dragger) stay where they
are, outside the group, lit by copies of the headlight so they look as before; picking follows
the roots' paths wherever they are, since FreeCAD finds the view provider of a picked path from
the nodes along it.
"""

import json
import math

import FreeCAD as App

import ivshadow  # noqa: F401  (loads the plugin and registers the nodes with Coin)
from pivy import coin

__all__ = ["enable", "disable", "is_enabled", "group", "renderer_in_use", "refresh", "settings_from_preferences",
           "save_preferences", "stored_settings", "highlight_colours", "PRESETS", "PARAMETERS",
           "DEFAULTS", "META_KEY"]

# Where the add-on's preferences live in FreeCAD's parameters (Tools > Edit parameters).
PARAMETERS = "User parameter:BaseApp/Preferences/Mod/IvShadow"

# The direction the light travels, in document coordinates (z up; FreeCAD's default isometric
# camera looks along (-1, 1, -1)). Over the shoulder: from behind and to the left of that camera
# and high, so the lit faces face the viewer and shadows fall back and to the right. Top: straight
# down, shadows right under the parts. Front-left: from the front-left and high.
PRESETS = {
    "OverTheShoulder": (-0.35, 0.55, -1.0),
    "Top": (0.0, 0.0, -1.0),
    "FrontLeft": (0.6, 0.8, -1.0),
}

# The settings and their defaults (also the preferences' defaults). Colours are (r, g, b) in 0..1.
DEFAULTS = {
    "preset": "OverTheShoulder",
    # "Directional": a light from far away (the sun), travelling along the preset's direction;
    # "Point": a lamp at a place, by default on the preset's line through the model's centre,
    # `light_distance` times the model's size away from it (enable(light_location=...) names
    # the place in document coordinates instead).
    "light_type": "Directional",
    "light_distance": 2.0,
    "light_color": (1.0, 1.0, 1.0),
    "intensity": 1.0,
    "ground": True,
    # The ground's side, as a multiple of the model's largest horizontal extent.
    "ground_size": 3.0,
    "ground_color": (0.8, 0.8, 0.8),
    # 0 (opaque) .. 100 (invisible), as FreeCAD's own Transparency property.
    "ground_transparency": 0,
    # SoTransparentShadowGroup.renderer: AUTO traces on the CPU where GL is a software
    # rasteriser (Mesa's llvmpipe) and rasterises on a GPU.
    "renderer": "AUTO",
    # FreeCAD's transparent parts: "Exact" composites them in depth order per pixel (the
    # group's transparency PEELED); "FreeCAD" leaves them to Coin's blending, as FreeCAD draws
    # them without shadows (COIN_BLENDING).
    "transparency": "Exact",
    # A dragger on the light in the view: turning it turns the light.
    "dragger": False,
}

_TRANSPARENCY = {"Exact": "PEELED", "FreeCAD": "COIN_BLENDING"}
_LIGHT_TYPES = {"Directional": "DeepShadowDirectionalLight", "Point": "DeepShadowLight"}

_NAMES = {"dragger": "IvShadowLightDragger", "lamp_dragger": "IvShadowLampDragger",
          "group": "IvShadowGroup", "light": "IvShadowLight", "ground": "IvShadowGround",
          "model": "IvShadowModel", "host_lights": "IvShadowHostLights",
          "highlight": "IvShadowHighlight"}


def _type(name):
    node = coin.SoType.fromName(coin.SbName(name)).createInstance()
    if node is None:
        raise RuntimeError("the ivshadow plugin did not register %s with Coin" % name)
    return node


def _address(node):
    # pivy makes a new wrapper for every node it returns; the C++ address names the node.
    return int(node.this)


def _colour_from_parameter(value):
    # FreeCAD stores colours as 0xRRGGBBAA in an unsigned parameter.
    return (((value >> 24) & 0xFF) / 255.0, ((value >> 16) & 0xFF) / 255.0,
            ((value >> 8) & 0xFF) / 255.0)


def _colour_to_parameter(colour):
    r, g, b = (max(0, min(255, int(round(c * 255)))) for c in colour)
    return (r << 24) | (g << 16) | (b << 8)


def settings_from_preferences():
    """The settings stored in FreeCAD's parameters (PARAMETERS), DEFAULTS where none is set."""
    group = App.ParamGet(PARAMETERS)
    settings = dict(DEFAULTS)
    settings["preset"] = group.GetString("LightPreset", DEFAULTS["preset"])
    if settings["preset"] not in PRESETS:
        settings["preset"] = DEFAULTS["preset"]
    settings["light_type"] = group.GetString("LightType", DEFAULTS["light_type"])
    if settings["light_type"] not in _LIGHT_TYPES:
        settings["light_type"] = DEFAULTS["light_type"]
    settings["light_distance"] = group.GetFloat("LightDistance", DEFAULTS["light_distance"])
    settings["light_color"] = _colour_from_parameter(
        group.GetUnsigned("LightColor", _colour_to_parameter(DEFAULTS["light_color"])))
    settings["intensity"] = group.GetFloat("LightIntensity", DEFAULTS["intensity"])
    settings["ground"] = group.GetBool("Ground", DEFAULTS["ground"])
    settings["ground_size"] = group.GetFloat("GroundSize", DEFAULTS["ground_size"])
    settings["ground_color"] = _colour_from_parameter(
        group.GetUnsigned("GroundColor", _colour_to_parameter(DEFAULTS["ground_color"])))
    settings["ground_transparency"] = group.GetInt("GroundTransparency",
                                                   DEFAULTS["ground_transparency"])
    settings["renderer"] = group.GetString("Renderer", DEFAULTS["renderer"])
    settings["transparency"] = group.GetString("Transparency", DEFAULTS["transparency"])
    if settings["transparency"] not in _TRANSPARENCY:
        settings["transparency"] = DEFAULTS["transparency"]
    settings["dragger"] = group.GetBool("LightDragger", DEFAULTS["dragger"])
    return settings


def save_preferences(settings):
    """Stores `settings` (keys of DEFAULTS) in FreeCAD's parameters."""
    group = App.ParamGet(PARAMETERS)
    group.SetString("LightPreset", settings["preset"])
    group.SetString("LightType", settings["light_type"])
    group.SetFloat("LightDistance", float(settings["light_distance"]))
    group.SetUnsigned("LightColor", _colour_to_parameter(settings["light_color"]))
    group.SetFloat("LightIntensity", float(settings["intensity"]))
    group.SetBool("Ground", bool(settings["ground"]))
    group.SetFloat("GroundSize", float(settings["ground_size"]))
    group.SetUnsigned("GroundColor", _colour_to_parameter(settings["ground_color"]))
    group.SetInt("GroundTransparency", int(settings["ground_transparency"]))
    group.SetString("Renderer", settings["renderer"])
    group.SetString("Transparency", settings["transparency"])
    group.SetBool("LightDragger", bool(settings["dragger"]))


def _active_view(view):
    if view is not None:
        return view
    import FreeCADGui as Gui
    document = Gui.ActiveDocument
    view = document.ActiveView if document else None
    if view is None or not hasattr(view, "getSceneGraph"):
        raise RuntimeError("ivshadow.freecad: no active 3D view")
    return view


def _document_of(view):
    """The name of the document `view` shows: the one among its 3D views with its scene."""
    import FreeCADGui as Gui
    address = _address(view.getSceneGraph())
    for name in App.listDocuments():
        for candidate in Gui.getDocument(name).mdiViewsOfType("Gui::View3DInventor"):
            if _address(candidate.getSceneGraph()) == address:
                return name
    raise RuntimeError("ivshadow.freecad: the view shows no open document")


def _unit(vector):
    x, y, z = (float(c) for c in vector)
    length = math.sqrt(x * x + y * y + z * z)
    if length == 0:
        raise ValueError("light_direction: a direction of zero length")
    return (x / length, y / length, z / length)


class _Shadows:
    """What enable() added to one view, and how to take it out again."""

    def __init__(self, view):
        import FreeCADGui as Gui
        self.view = view
        self.selection = view.getSceneGraph()  # FreeCAD's SoFCUnifiedSelection
        self.top = view.getViewer().getSoRenderManager().getSceneGraph()
        self.document = _document_of(view)

        self.group = _type("TransparentShadowGroup")
        self.group.setName(_NAMES["group"])
        self.light = _type(_LIGHT_TYPES[DEFAULTS["light_type"]])
        self.light.setName(_NAMES["light"])
        self.group.addChild(self.light)
        self.location = None  # a point light's place named by enable(light_location=...)

        # The ground: unpickable (a click on it selects nothing, as on the background), under a
        # switch that hides it when the camera looks at it from below.
        self.ground = coin.SoSeparator()
        self.ground.setName(_NAMES["ground"])
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        self.ground.addChild(pick)
        self.ground_switch = coin.SoSwitch()
        self.ground_switch.whichChild = coin.SO_SWITCH_NONE
        self.ground.addChild(self.ground_switch)
        self.ground_material = coin.SoMaterial()
        self.ground_coordinates = coin.SoCoordinate3()
        normal = coin.SoNormal()
        normal.vector.setValue(coin.SbVec3f(0, 0, 1))
        binding = coin.SoNormalBinding()
        binding.value = coin.SoNormalBinding.OVERALL
        face = coin.SoFaceSet()
        face.numVertices.setValue(4)
        shape = coin.SoSeparator()
        for node in (self.ground_material, self.ground_coordinates, normal, binding, face):
            shape.addChild(node)
        self.ground_switch.addChild(shape)
        self.group.addChild(self.ground)

        # The view providers' roots, in FreeCAD's order.
        self.model = coin.SoGroup()
        self.model.setName(_NAMES["model"])
        self.group.addChild(self.model)

        # FreeCAD's highlight of faces, drawn again for the tracer (_Highlight, below).
        self.highlight = _Highlight(self)
        self.group.addChild(self.highlight.root)

        # Copies of FreeCAD's headlight and backlight for FreeCAD's own nodes after the group.
        # The lights themselves sit before the camera, in eye coordinates; each copy's
        # direction is the light's turned by the camera's orientation, worked out by engines
        # (SoComposeMatrix, SoTransformVec3f) rather than by a rotation node in the graph:
        # FreeCAD's selection actions (SoSelectionElementAction, SoHighlightElementAction)
        # traverse every group without the model matrix element, and a transform separator
        # there crashes FreeCAD when a selection is cleared. The connections keep the engines.
        self.host_lights = coin.SoGroup()
        self.host_lights.setName(_NAMES["host_lights"])
        self.camera_matrix = coin.SoComposeMatrix()
        self.host_light_engines = []
        self.turned_off = []  # FreeCAD's lights this object turned off
        for index in range(self.top.getNumChildren()):
            node = self.top.getChild(index)
            if node.isOfType(coin.SoDirectionalLight.getClassTypeId()) and node.on.getValue():
                turn = coin.SoTransformVec3f()
                turn.matrix.connectFrom(self.camera_matrix.matrix)
                turn.vector.connectFrom(node.direction)
                copy = coin.SoDirectionalLight()
                copy.direction.connectFrom(turn.direction)
                copy.color.connectFrom(node.color)
                copy.intensity.connectFrom(node.intensity)
                self.host_lights.addChild(copy)
                self.host_light_engines.append(turn)
                self.turned_off.append(node)
        self.camera = None

        self.settings = dict(DEFAULTS)
        self.direction = _unit(PRESETS[DEFAULTS["preset"]])
        self.bounds = None
        self.known_children = None
        # Immediate (priority 0): FreeCAD appends a new object's root and a script may call
        # saveImage at once, before Coin's delay queue runs; the callback only compares the
        # node's few children, so it may run on every change below it.
        self.selection_sensor = coin.SoNodeSensor(self._selection_changed, None)
        self.selection_sensor.setPriority(0)
        self.syncing = False
        self.model_sensor = coin.SoNodeSensor(self._model_changed, None)
        self.top_sensor = coin.SoNodeSensor(self._top_changed, None)

        # The light's dragger (Coin's SoDirectionalLightDragger: its arrow is the light's
        # direction), after the group so that it casts no shadow and is drawn by GL, lit by the
        # headlight's copies; placed above the model's centre and sized after it. Its rotation
        # is the light's direction turned from (0, 0, -1), as SoDirectionalLightManip has it.
        self.dragger_root = coin.SoSeparator()
        self.dragger_root.setName(_NAMES["dragger"])
        self.dragger_place = coin.SoTransform()
        self.dragger = coin.SoDirectionalLightDragger()
        self.dragger_root.addChild(self.dragger_place)
        self.dragger_root.addChild(self.dragger)
        self.turning = False
        self.dragger_sensor = coin.SoFieldSensor(self._dragger_turned, None)
        self.dragger_sensor.setPriority(0)
        # A point light's dragger (Coin's SoPointLightDragger, moved along its three axes):
        # its place is the lamp's. Coin's dragger is about 2 units across; a scale sizes it
        # after the model, so its translation is the lamp's place divided by that scale.
        self.lamp_dragger_root = coin.SoSeparator()
        self.lamp_dragger_root.setName(_NAMES["lamp_dragger"])
        self.lamp_dragger_scale = coin.SoScale()
        self.lamp_dragger = coin.SoPointLightDragger()
        self.lamp_dragger_root.addChild(self.lamp_dragger_scale)
        self.lamp_dragger_root.addChild(self.lamp_dragger)
        self.lamp_dragger_sensor = coin.SoFieldSensor(self._lamp_dragged, None)
        self.lamp_dragger_sensor.setPriority(0)

    # -- putting the group in and taking it out -------------------------------------------------

    def insert(self):
        roots = _view_provider_roots(self.document)
        selection = self.selection
        # After FreeCAD's leading event callback, which puts the GL widget and render action
        # into the state for what follows it (draggers read them when handling events).
        index = 0
        while index < selection.getNumChildren() and \
                selection.getChild(index).isOfType(coin.SoEventCallback.getClassTypeId()):
            index += 1
        moved = []
        position = 0
        while position < selection.getNumChildren():
            child = selection.getChild(position)
            if _address(child) in roots:
                moved.append(child)
                selection.removeChild(position)
            else:
                position += 1
        for child in moved:
            self.model.addChild(child)
        selection.insertChild(self.group, index)
        selection.insertChild(self.host_lights, index + 1)
        self._show_dragger()
        for light in self.turned_off:
            light.on = False
        self._follow_camera()
        self._update_bounds()
        self.known_children = _children(selection)
        self.selection_sensor.attach(selection)
        self.model_sensor.attach(self.model)
        self.top_sensor.attach(self.top)
        _observer.watch()
        self.highlight.update()

    def sensors(self):
        """The sensors this object attaches, to be stopped with it."""
        return (self.selection_sensor, self.model_sensor, self.top_sensor, self.dragger_sensor,
                self.lamp_dragger_sensor)

    def remove(self):
        for sensor in self.sensors():
            sensor.detach()
        self.highlight.stop()
        selection = self.selection
        for root in (self.dragger_root, self.lamp_dragger_root):
            index = selection.findChild(root)
            if index >= 0:
                selection.removeChild(index)
        index = selection.findChild(self.group)
        if index >= 0:
            selection.removeChild(index)
        index = selection.findChild(self.host_lights)
        if index >= 0:
            selection.removeChild(index)
        # Back at the end, in their order: where FreeCAD's addViewProvider put them.
        for index in range(self.model.getNumChildren()):
            selection.addChild(self.model.getChild(index))
        self.model.removeAllChildren()
        for light in self.turned_off:
            light.on = True
        self.turned_off = []
        if self.camera is not None:
            self.camera_matrix.rotation.disconnect()
            self.camera = None

    # -- settings -------------------------------------------------------------------------------

    def apply(self, direction, settings, location=None):
        self.direction = direction
        self.settings = settings
        self.location = location
        wanted = _LIGHT_TYPES[settings["light_type"]]
        if self.light.getTypeId().getName().getString() != wanted:
            light = _type(wanted)
            light.setName(_NAMES["light"])
            self.group.replaceChild(self.light, light)
            self.light = light
        if self._is_point():
            self._place_light()
        else:
            self.light.direction.setValue(coin.SbVec3f(*direction))
        self.light.color.setValue(coin.SbColor(*settings["light_color"]))
        self.light.intensity = float(settings["intensity"])
        if not self.group.renderer.set(str(settings["renderer"])):
            raise ValueError("renderer: AUTO, RASTER or TRACER, not %r" % settings["renderer"])
        for name, value in settings.get("fields", {}).items():
            field = self.group.getField(name)
            if field is None or not field.set(str(value)):
                raise ValueError("TransparentShadowGroup has no field %r taking %r" %
                                 (name, value))
        self.ground_material.diffuseColor.setValue(coin.SbColor(*settings["ground_color"]))
        self.ground_material.transparency = float(settings["ground_transparency"]) / 100.0
        # The look's name, or the group's own value of the field (PEELED, COIN_BLENDING).
        transparency = _TRANSPARENCY.get(settings["transparency"], settings["transparency"])
        if transparency not in _TRANSPARENCY.values():
            raise ValueError("transparency: Exact or FreeCAD, not %r" % settings["transparency"])
        self.group.transparency.set(transparency)
        self._turn_dragger()
        if self.selection.findChild(self.group) >= 0:  # not yet on the first enable()
            self._show_dragger()
        self.bounds = None
        self._update_bounds()
        if self.selection.findChild(self.group) >= 0:
            self.highlight.update()  # the renderer may have changed

    # -- keeping up with FreeCAD ----------------------------------------------------------------

    def _selection_changed(self, data, sensor):
        # Whatever changes below the SoFCUnifiedSelection node wakes this; only a change of its
        # own children matters, and that is rare.
        if self.syncing:  # woken by its own moves
            return
        children = _children(self.selection)
        if children == self.known_children:
            return
        self.syncing = True
        try:
            self._move_new_roots()
        finally:
            self.syncing = False

    def _move_new_roots(self):
        roots = _view_provider_roots(self.document)
        in_model = set(_children(self.model))
        position = 0
        while position < self.selection.getNumChildren():
            child = self.selection.getChild(position)
            address = _address(child)
            if address in roots:
                self.selection.removeChild(position)
                # FreeCAD may add a root again that it could not find to remove (a root it
                # moves in and out of the scene as a group claims the object).
                if address not in in_model:
                    self.model.addChild(child)
            else:
                position += 1
        self.known_children = _children(self.selection)

    def forget(self, root):
        """Takes a deleted view provider's root out of the group."""
        index = self.model.findChild(root)
        if index >= 0:
            self.model.removeChild(index)

    def _model_changed(self, data, sensor):
        self._update_bounds()
        # A recompute gives a highlighted face new triangles (FreeCAD keeps it selected).
        self.highlight.schedule()

    def _top_changed(self, data, sensor):
        # Closing a document with shadows, FreeCAD deletes its view before the Gui document
        # observer hears of it (slotDeletedDocument stops the sensors), and the scene graph's
        # changes meanwhile wake this sensor: the view's wrapper then raises on any use.
        try:
            self.view.getViewer()
        except RuntimeError:
            for each in self.sensors():
                each.detach()
            return
        self._follow_camera()

    def _follow_camera(self):
        # The render manager's camera, None until the view has one: the view's getCameraNode()
        # dereferences it without a check, and crashed FreeCAD where a document just opened had
        # none yet.
        camera = self.view.getViewer().getSoRenderManager().getCamera()
        if camera is None:
            return
        if self.camera is None or _address(camera) != _address(self.camera):
            self.camera_matrix.rotation.connectFrom(camera.orientation)
            self.camera = camera
        self._show_ground()

    def _show_ground(self):
        visible = self.bounds is not None and self.settings["ground"]
        if visible and self.camera is not None:
            ground_height = self.bounds[2]
            if self.camera.isOfType(coin.SoOrthographicCamera.getClassTypeId()):
                # A parallel projection sees the ground's underside whenever it looks up.
                looking = self.camera.orientation.getValue().multVec(coin.SbVec3f(0, 0, -1))
                visible = looking[2] < 0
            else:
                visible = self.camera.position.getValue()[2] > ground_height
        wanted = 0 if visible else coin.SO_SWITCH_NONE
        if self.ground_switch.whichChild.getValue() != wanted:
            self.ground_switch.whichChild = wanted

    def _update_bounds(self):
        action = coin.SoGetBoundingBoxAction(coin.SbViewportRegion())
        action.apply(self.model)
        box = action.getBoundingBox()
        if box.isEmpty():
            bounds = None
        else:
            low = box.getMin().getValue()
            high = box.getMax().getValue()
            bounds = tuple(low) + tuple(high)
            if not all(math.isfinite(value) for value in bounds):
                bounds = None
        if bounds == self.bounds and bounds is not None:
            return
        self.bounds = bounds
        if bounds is not None:
            if self._is_point():
                self._place_light()
            self._place_ground(bounds)
            self._place_dragger(bounds)
        self._show_ground()

    def _is_point(self):
        return self.settings["light_type"] == "Point"

    def _light_place(self):
        """A point light's place: the one named, or on the preset's line through the model's
        centre, light_distance times the model's size before it (where the light comes from)."""
        if self.location is not None:
            return self.location
        if self.bounds is None:
            return (0.0, 0.0, 0.0)
        x0, y0, z0, x1, y1, z1 = self.bounds
        size = max(x1 - x0, y1 - y0, z1 - z0, 1e-6)
        distance = float(self.settings["light_distance"]) * size
        centre = ((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2)
        return tuple(c - d * distance for c, d in zip(centre, self.direction))

    def _place_light(self):
        place = self._light_place()
        self.light.location.setValue(coin.SbVec3f(*place))
        self._move_lamp_dragger(place)

    def _show_dragger(self):
        # The directional light's dragger turns it, the point light's moves it.
        for root, sensor, field, shown in (
                (self.dragger_root, self.dragger_sensor, self.dragger.rotation,
                 self.settings["dragger"] and not self._is_point()),
                (self.lamp_dragger_root, self.lamp_dragger_sensor, self.lamp_dragger.translation,
                 self.settings["dragger"] and self._is_point())):
            index = self.selection.findChild(root)
            if shown and index < 0:
                self.selection.insertChild(root, self.selection.findChild(self.host_lights) + 1)
                sensor.attach(field)
            elif not shown and index >= 0:
                sensor.detach()
                self.selection.removeChild(index)

    def _move_lamp_dragger(self, place):
        """The point light's dragger where the lamp is (not the other way round)."""
        scale = self.lamp_dragger_scale.scaleFactor.getValue()[0]
        self.turning = True
        try:
            self.lamp_dragger.translation.setValue(coin.SbVec3f(*(c / scale for c in place)))
        finally:
            self.turning = False

    def _lamp_dragged(self, data, sensor):
        # The user moved the lamp's dragger: the lamp follows, and the ground with its shadow;
        # the place is kept as if enable(light_location=...) had named it.
        if self.turning or not self._is_point():
            return
        scale = self.lamp_dragger_scale.scaleFactor.getValue()[0]
        moved = self.lamp_dragger.translation.getValue().getValue()
        self.location = tuple(float(c) * scale for c in moved)
        self.light.location.setValue(coin.SbVec3f(*self.location))
        if self.bounds is not None:
            self._place_ground(self.bounds)
        _store(self.document, self.direction, self.settings, self.location)

    def _turn_dragger(self):
        """The dragger's rotation from the light's direction (not the other way round)."""
        self.turning = True
        try:
            self.dragger.rotation.setValue(
                coin.SbRotation(coin.SbVec3f(0, 0, -1), coin.SbVec3f(*self.direction)))
        finally:
            self.turning = False

    def _dragger_turned(self, data, sensor):
        # The user turned the dragger: the light follows, and the ground with its shadow.
        if self.turning or self._is_point():
            return
        turned = self.dragger.rotation.getValue().multVec(coin.SbVec3f(0, 0, -1)).getValue()
        self.direction = _unit(turned)
        self.light.direction.setValue(coin.SbVec3f(*self.direction))
        if self.bounds is not None:
            self._place_ground(self.bounds)
        _store(self.document, self.direction, self.settings, self.location)

    def _place_dragger(self, bounds):
        x0, y0, z0, x1, y1, z1 = bounds
        extent = max(x1 - x0, y1 - y0, z1 - z0, 1e-6)
        # Above the model's top, a fifth of its size across (Coin's dragger is about 2 units).
        self.dragger_place.translation.setValue(
            coin.SbVec3f((x0 + x1) / 2, (y0 + y1) / 2, z1 + 0.2 * extent))
        scale = 0.1 * extent
        self.dragger_place.scaleFactor.setValue(coin.SbVec3f(scale, scale, scale))
        self.lamp_dragger_scale.scaleFactor.setValue(coin.SbVec3f(scale, scale, scale))
        if self._is_point():
            self._move_lamp_dragger(self._light_place())

    def _place_ground(self, bounds):
        x0, y0, z0, x1, y1, z1 = bounds
        extent = max(x1 - x0, y1 - y0, z1 - z0)
        if extent <= 0:
            extent = 1.0
        footprint = max(x1 - x0, y1 - y0, extent * 0.5)
        margin = float(self.settings["ground_size"]) * footprint
        if self._is_point():
            # Where the lamp carries the corners of the model's top down to the ground: the
            # ground covers the model's footprint and that shadow, with the margin the size
            # asks for around the model.
            lx, ly, lz = self._light_place()
            xs, ys = [x0, x1], [y0, y1]
            if lz > z1 + 1e-6 * extent:
                scale = min((lz - z0) / (lz - z1), 10.0)
                for x in (x0, x1):
                    for y in (y0, y1):
                        xs.append(lx + (x - lx) * scale)
                        ys.append(ly + (y - ly) * scale)
            else:  # a lamp level with the top or below it: the shadow runs off anyway
                xs += [x0 - 5 * extent, x1 + 5 * extent]
                ys += [y0 - 5 * extent, y1 + 5 * extent]
            cx = (min(xs) + max(xs)) / 2
            cy = (min(ys) + max(ys)) / 2
            half = (max(max(xs) - min(xs), max(ys) - min(ys)) + margin - footprint) / 2
        else:
            dx, dy, dz = self.direction
            # Where the light carries the top of the model down to the ground: the ground is
            # centred between the model and that shadow, and grows by the shadow's offset.
            drop = z1 - z0
            shift = (0.0, 0.0) if dz >= -1e-6 else (dx / -dz * drop, dy / -dz * drop)
            shift_length = math.hypot(*shift)
            if shift_length > 10 * extent:  # a light almost level: the shadow runs off anyway
                shift = (shift[0] / shift_length * 10 * extent,
                         shift[1] / shift_length * 10 * extent)
                shift_length = 10 * extent
            cx = (x0 + x1) / 2 + shift[0] / 2
            cy = (y0 + y1) / 2 + shift[1] / 2
            half = (margin + shift_length) / 2
        # Just below the lowest point, so that faces lying on it do not fight with it for
        # depth; a thousandth of the model's size is far below GL's depth resolution at any
        # zoom that shows the model, and no visible gap under it.
        z = z0 - 1e-3 * extent
        points = [(cx - half, cy - half, z), (cx + half, cy - half, z),
                  (cx + half, cy + half, z), (cx - half, cy + half, z)]
        self.ground_coordinates.point.setValues(0, 4, points)


def _children(group):
    return [_address(group.getChild(i)) for i in range(group.getNumChildren())]


def _view_provider_roots(document_name):
    """The addresses of the root nodes of the view providers of a Gui document."""
    import FreeCADGui as Gui
    roots = set()
    if not document_name:
        return roots
    gui_document = Gui.getDocument(document_name)
    for obj in gui_document.Document.Objects:
        view_object = gui_document.getObject(obj.Name)
        root = getattr(view_object, "RootNode", None) if view_object else None
        if root is not None:
            roots.add(_address(root))
    return roots


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
                indices = self.coord_index[self.starts[face]:self.starts[face] + 4 * self.counts[face]]
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


class _SelectionObserver:
    """FreeCAD's selection and pre-selection (Gui.Selection.addObserver): each change updates
    the overlay of the views with shadows of its document."""

    def __init__(self):
        self.preselection = None  # (document, object, subname) while FreeCAD pre-selects

    def _changed(self, document):
        # At once, so that a script's next saveImage shows the change: FreeCAD calls its
        # observers after its own picking and selection actions, outside any traversal of the
        # overlay's nodes, and the overlay's changes stay below the group.
        for state in list(_states.values()):
            if not document or state.document == document:
                state.highlight.update()

    def addSelection(self, document, obj, sub, point):  # noqa: N802  (FreeCAD's names)
        self._changed(document)

    def removeSelection(self, document, obj, sub):  # noqa: N802
        self._changed(document)

    def setSelection(self, document):  # noqa: N802
        self._changed(document)

    def clearSelection(self, document):  # noqa: N802
        self._changed(document)

    def setPreselection(self, document, obj, sub):  # noqa: N802
        self.preselection = (document, obj, sub)
        self._changed(document)

    def removePreselection(self, document, obj, sub):  # noqa: N802
        self.preselection = None
        self._changed(document)


_selection_observer = _SelectionObserver()


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
            built = self._piece(document, object_name, sub, colour, order * _HIGHLIGHT_OFFSET * size)
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


class _DocumentObserver:
    """Keeps the groups consistent as FreeCAD deletes objects and closes documents."""

    def __init__(self):
        self.watching = False

    def watch(self):
        if not self.watching:
            import FreeCADGui as Gui
            Gui.addDocumentObserver(self)
            Gui.Selection.addObserver(_selection_observer)
            self.watching = True

    def slotDeletedObject(self, view_provider):
        try:
            name = view_provider.Object.Name
            document = view_provider.Object.Document.Name
        except Exception:  # noqa: BLE001  (a view provider without an object)
            name = document = None
        if document is not None:
            _drop_meshes(document, name)
            presel = _selection_observer.preselection
            if presel is not None and presel[0] == document and presel[1] == name:
                _selection_observer.preselection = None
        root = getattr(view_provider, "RootNode", None)
        if root is None:
            return
        for state in _states.values():
            state.forget(root)
            if state.document == document:
                state.highlight.schedule()

    def slotDeletedDocument(self, gui_document):
        name = gui_document.Document.Name
        for key, state in list(_states.items()):
            if state.document == name:
                # The view goes with the document; only the sensors must stop (they would
                # otherwise wake on nodes FreeCAD is about to destroy).
                for sensor in state.sensors():
                    sensor.detach()
                state.highlight.stop()
                del _states[key]
        _drop_meshes(name)
        if _selection_observer.preselection and _selection_observer.preselection[0] == name:
            _selection_observer.preselection = None


_states = {}
_observer = _DocumentObserver()


# The key of a document's Meta map that holds its shadows' settings (JSON), saved with it.
META_KEY = "IvShadow"


def stored_settings(document):
    """The shadow settings saved with an App document (its Meta map, key META_KEY), or {}."""
    try:
        return json.loads(document.Meta.get(META_KEY, "{}"))
    except (ValueError, AttributeError):
        return {}


def _store(document_name, direction, settings, location):
    document = App.getDocument(document_name)
    stored = {key: (list(value) if isinstance(value, tuple) else value)
              for key, value in settings.items() if key in DEFAULTS}
    stored["light_direction"] = list(direction)
    stored["light_location"] = list(location) if location is not None else None
    # Shadows are on: a document saved now and opened again gets them back (init_gui.py).
    stored["enabled"] = True
    _write_meta(document, stored)


def _write_meta(document, stored):
    text = json.dumps(stored, sort_keys=True)
    meta = document.Meta
    if meta.get(META_KEY) != text:
        meta[META_KEY] = text
        document.Meta = meta


def _store_disabled(document_name):
    try:
        document = App.getDocument(document_name)
    except NameError:  # closed meanwhile
        return
    stored = stored_settings(document)
    if stored.get("enabled"):
        stored["enabled"] = False
        _write_meta(document, stored)


def _resolve(light_direction, ground, settings, light_location=None, stored=None):
    resolved = settings_from_preferences()
    from_stored = False
    if stored:
        # The document's own settings over the preferences (docs/FREECAD.md, "Per document").
        for key in DEFAULTS:
            if key in stored:
                value = stored[key]
                resolved[key] = tuple(value) if isinstance(value, list) else value
        if light_direction is None and light_location is None:
            if stored.get("light_location") is not None and resolved["light_type"] == "Point":
                light_location = stored["light_location"]
            elif stored.get("light_direction") is not None:
                light_direction = stored["light_direction"]
            from_stored = True
    fields = {}
    for key, value in settings.items():
        if key in DEFAULTS:
            resolved[key] = value
        elif key[:1].islower() and key.replace("_", "").isalnum():
            # Any other keyword names a field of the TransparentShadowGroup (movingResolution,
            # transparency, ...), set as in a file.
            fields[key] = value
        else:
            raise TypeError("enable(): unknown setting %r" % key)
    if ground is not None:
        resolved["ground"] = bool(ground)
    if resolved["preset"] not in PRESETS:
        raise ValueError("preset: one of %s" % ", ".join(PRESETS))
    if light_direction is not None and light_location is None and \
            "light_type" not in settings and not from_stored:
        resolved["light_type"] = "Directional"  # a direction named: a light from far away
    if light_location is not None:
        resolved["light_type"] = "Point"
        light_location = tuple(float(c) for c in light_location)
        if len(light_location) != 3 or not all(math.isfinite(c) for c in light_location):
            raise ValueError("light_location: three finite coordinates")
    if resolved["light_type"] not in _LIGHT_TYPES:
        raise ValueError("light_type: Directional or Point, not %r" % resolved["light_type"])
    direction = _unit(light_direction if light_direction is not None
                      else PRESETS[resolved["preset"]])
    resolved["fields"] = fields
    return direction, resolved, light_location


def enable(view=None, *, light_direction=None, ground=None, light_location=None, **settings):
    """Shadows in `view` (a FreeCAD 3D view; the active one when None).

    light_direction: the direction the light travels in document coordinates, as Coin's
    DirectionalLight.direction (None: the preferences' preset); with a point light, the line
    from its place through the model's centre. light_location: a point light at this place in
    document coordinates (None: the preferences' light). ground: the automatic ground on or off
    (None: the preference). settings: any of DEFAULTS' keys (preset, light_type,
    light_distance, light_color, intensity, ground_size, ground_color, ground_transparency, renderer), or fields of the
    TransparentShadowGroup by name (movingResolution=0.5, transparency="COIN_BLENDING").
    Called on a view with shadows, changes their settings."""
    view = _active_view(view)
    document = _document_of(view)
    direction, resolved, location = _resolve(light_direction, ground, settings, light_location,
                                             stored_settings(App.getDocument(document)))
    key = _address(view.getSceneGraph())
    state = _states.get(key)
    if state is None:
        state = _Shadows(view)
        state.apply(direction, resolved, location)
        state.insert()
        _states[key] = state
    else:
        state.apply(direction, resolved, location)
    _store(document, direction, resolved, location)
    return state.group


def disable(view=None):
    """FreeCAD's own picture in `view` again: the model back where FreeCAD keeps it, its
    headlight as it was, and the document's settings saying shadows are off (saved now, it
    opens without them). Nothing happens in a view without shadows."""
    view = _active_view(view)
    state = _states.pop(_address(view.getSceneGraph()), None)
    if state is not None:
        state.remove()
        _store_disabled(state.document)


def is_enabled(view=None):
    """Whether `view` (the active 3D view when None) has shadows."""
    view = _active_view(view)
    return _address(view.getSceneGraph()) in _states


def refresh():
    """Every view with shadows takes the preferences' settings again (the preferences page
    calls this when it saves)."""
    for state in _states.values():
        direction, resolved, location = _resolve(None, None, {})
        state.apply(direction, resolved, location)
        _store(state.document, direction, resolved, location)


def group(view=None):
    """The TransparentShadowGroup of `view`, or None: its fields and statistics."""
    state = _states.get(_address(_active_view(view).getSceneGraph()))
    return state.group if state else None


def renderer_in_use(view=None):
    """How `view` (the active 3D view when None) drew its shadows in its last frame, the
    renderer setting's AUTO resolved: "TRACER" (traced on the CPU: a machine without a GPU) or
    "RASTER" (GL's shading on a GPU); None without shadows or before their first frame."""
    shadow_group = group(view)
    return ivshadow.renderer_in_use(shadow_group) if shadow_group is not None else None
