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

__all__ = ["enable", "disable", "is_enabled", "group", "refresh", "settings_from_preferences",
           "save_preferences", "stored_settings", "PRESETS", "PARAMETERS", "DEFAULTS", "META_KEY"]

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

_NAMES = {"dragger": "IvShadowLightDragger", "group": "IvShadowGroup", "light": "IvShadowLight", "ground": "IvShadowGround",
          "model": "IvShadowModel", "host_lights": "IvShadowHostLights"}


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

    def remove(self):
        for sensor in (self.selection_sensor, self.model_sensor, self.top_sensor,
                       self.dragger_sensor):
            sensor.detach()
        selection = self.selection
        index = selection.findChild(self.dragger_root)
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

    def _top_changed(self, data, sensor):
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
        self.light.location.setValue(coin.SbVec3f(*self._light_place()))

    def _show_dragger(self):
        index = self.selection.findChild(self.dragger_root)
        # The dragger turns a directional light; a point light is placed by the preferences.
        shown = self.settings["dragger"] and not self._is_point()
        if shown and index < 0:
            self.selection.insertChild(self.dragger_root,
                                       self.selection.findChild(self.host_lights) + 1)
            self.dragger_sensor.attach(self.dragger.rotation)
        elif not shown and index >= 0:
            self.dragger_sensor.detach()
            self.selection.removeChild(index)

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


class _DocumentObserver:
    """Keeps the groups consistent as FreeCAD deletes objects and closes documents."""

    def __init__(self):
        self.watching = False

    def watch(self):
        if not self.watching:
            import FreeCADGui as Gui
            Gui.addDocumentObserver(self)
            self.watching = True

    def slotDeletedObject(self, view_provider):
        root = getattr(view_provider, "RootNode", None)
        if root is None:
            return
        for state in _states.values():
            state.forget(root)

    def slotDeletedDocument(self, gui_document):
        name = gui_document.Document.Name
        for key, state in list(_states.items()):
            if state.document == name:
                # The view goes with the document; only the sensors must stop (they would
                # otherwise wake on nodes FreeCAD is about to destroy).
                for sensor in (state.selection_sensor, state.model_sensor, state.top_sensor,
                               state.dragger_sensor):
                    sensor.detach()
                del _states[key]


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
    text = json.dumps(stored, sort_keys=True)
    meta = document.Meta
    if meta.get(META_KEY) != text:
        meta[META_KEY] = text
        document.Meta = meta


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
    headlight as it was. Nothing happens in a view without shadows."""
    view = _active_view(view)
    state = _states.pop(_address(view.getSceneGraph()), None)
    if state is not None:
        state.remove()


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
