"""The per-view shadow state (_Shadows): what enable() adds to one 3D view, how it keeps up
with FreeCAD's changes to the view's scene, and how to take it out again (the package's
docstring says where the group goes, and why)."""

import math

from pivy import coin

from ._documents import _observer
from ._highlight import _Highlight
from ._scene import _NAMES, _address, _children, _document_of, _type, _view_provider_roots
from ._settings import _LIGHT_TYPES, _TRANSPARENCY, DEFAULTS, PRESETS, _store, _unit


class _Shadows:
    """What enable() added to one view, and how to take it out again."""

    def __init__(self, view):
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

        # FreeCAD's highlight of faces, drawn again for the tracer (_Highlight, _highlight.py).
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
