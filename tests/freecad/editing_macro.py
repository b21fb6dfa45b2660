"""FreeCAD macro of the add-on's light-and-editing test (run by freecad_test.py inside FreeCAD
0.20's GUI): a point light's place (from the API and from the preferences) moves the shadows
where the geometry puts them; the sketcher's edit mode and the Placement transform dragger
with shadows on. The scene is macro_common.make_scene's (a plane whose top is z = 0, a 30 mm
box at the origin, a red 50 % transparent sphere of radius 15 at (90, 0, 50)); AUTO renderer
(the CPU tracer on llvmpipe).
"""
import traceback

import FreeCAD as App
import FreeCADGui as Gui

from macro_common import LIGHT, check, finish, grey, live, make_scene, pixel_of, rgb, save

SIZE = (640, 480)

# The point light of the test: above and behind the box (+y), so that the box's shadow falls
# towards -y, where the isometric camera (looking from +x, -y, +z) sees it.
LAMP = (15.0, 80.0, 80.0)


def near(image, pixel, wanted, radius):
    for dy in range(-radius, radius + 1):
        for dx in range(-radius, radius + 1):
            x, y = pixel[0] + dx, pixel[1] + dy
            if 0 <= x < image.width() and 0 <= y < image.height() and wanted(rgb(image, (x, y))):
                return True
    return False


def count(image, centre, radius, wanted):
    found = 0
    for dy in range(-radius, radius + 1):
        for dx in range(-radius, radius + 1):
            x, y = centre[0] + dx, centre[1] + dy
            if 0 <= x < image.width() and 0 <= y < image.height() and wanted(rgb(image, (x, y))):
                found += 1
    return found


def point_light(document, view, shadows):
    # From the geometry (a plane point is in shadow when the segment from it to the lamp meets
    # the box, 0..30 on each axis):
    # - (15, -30, 0): towards the lamp along (0, 110, 80) it reaches the box's side y = 0 at
    #   t = 0.27, height 21.8, x = 15: inside the face, so in the lamp's shadow; towards the
    #   test's directional light (along -LIGHT = (-0.4, 0.3, 1)) it reaches y = 0 only at
    #   height 100, far above the box: lit by that light;
    # - (38, 15, 0): towards the lamp along (-23, 65, 80) it reaches x = 30 at t = 0.35, where
    #   y = 37.6 (beyond the box's 30) and it never enters the box: lit by the lamp; towards the
    #   directional light it reaches x = 30 at height 20, y = 21: inside, so in that light's
    #   shadow.
    # Both are seen by the camera (the ray from each towards (1, -1, 1) moves away from the
    # box). The shadow is under a quarter of the lit point (ambient light only), and the lit
    # point over 100 levels (the plane's 0.8 grey lit at cos 0.74 is about 150).
    lamp_shadow, lamp_lit = (15, -30, 0), (38, 15, 0)
    shadows.enable(view, light_direction=LIGHT)
    directional = save(view, "directional", SIZE)
    shadows.enable(view, light_location=LAMP)
    lamp = save(view, "point_light", SIZE)
    group = shadows.group(view)
    light = group.getChild(0)
    check("point light: a DeepShadowLight at the place named",
          light.getTypeId().getName().getString() == "DeepShadowLight" and
          all(abs(a - b) < 1e-4 for a, b in zip(light.location.getValue().getValue(), LAMP)),
          type=light.getTypeId().getName().getString(),
          location=list(light.location.getValue().getValue()))
    a = rgb(lamp, pixel_of(view, lamp_shadow, SIZE))
    b = rgb(lamp, pixel_of(view, lamp_lit, SIZE))
    check("point light: the box's shadow where the lamp puts it",
          grey(a) < 0.25 * grey(b) and grey(b) > 100, shadow=a, lit=b)
    a = rgb(directional, pixel_of(view, lamp_shadow, SIZE))
    b = rgb(directional, pixel_of(view, lamp_lit, SIZE))
    check("directional light: the same two points the other way round",
          grey(b) < 0.25 * grey(a) and grey(a) > 100, lamp_shadow_point=a, lamp_lit_point=b)

    # From the preferences: a point light on the preset's line through the model's centre,
    # LightDistance times the model's size from it. The model's bounds (the plane, the box,
    # the sphere) are x -50..150, y -100..100, z -1..65: centre (50, 0, 32), size 200; with
    # the preset Top (straight down) and distance 2 the lamp is 400 above the centre.
    saved = shadows.settings_from_preferences()
    shadows.save_preferences(dict(saved, light_type="Point", preset="Top", light_distance=2.0))
    # The document keeps the settings it was last shown with (its Meta map): taken out here, as
    # in a new document, so that the preferences apply.
    meta = document.Meta
    meta.pop(shadows.META_KEY, None)
    document.Meta = meta
    shadows.enable(view)  # the preferences' light: no light_location
    light = shadows.group(view).getChild(0)
    location = list(light.location.getValue().getValue()) \
        if light.getTypeId().getName().getString() == "DeepShadowLight" else None
    check("point light from the preferences: 2 x the model's size above its centre (Top)",
          location is not None and
          all(abs(a - b) < 1e-3 for a, b in zip(location, (50.0, 0.0, 432.0))),
          location=location)
    # Moving the model moves the lamp with it (it follows the model's bounds).
    document.Box.Placement.Base = App.Vector(0, 0, 100)  # the top goes to z 130
    document.recompute()
    Gui.updateGui()
    location = list(shadows.group(view).getChild(0).location.getValue().getValue())
    # Bounds now z -1..130: centre z 64.5, size 200 (x still spans 200): 464.5.
    check("point light follows the model's bounds", abs(location[2] - 464.5) < 1e-3,
          location=location)
    document.Box.Placement.Base = App.Vector(0, 0, 0)
    document.recompute()
    shadows.save_preferences(saved)
    shadows.enable(view, light_direction=LIGHT)
    light = shadows.group(view).getChild(0)
    check("back to a directional light",
          light.getTypeId().getName().getString() == "DeepShadowDirectionalLight",
          type=light.getTypeId().getName().getString())


def green(colour):
    r, g, b = colour
    return g > 150 and g > r + 80 and g > b + 80


def leave_edit(view, shadows, picture, what, refit=False):
    # Edit mode left: shadows are still on, and the box still casts its dark shadow where the
    # light puts it, against a lit point of the plane beside it.
    Gui.ActiveDocument.resetEdit()
    Gui.updateGui()
    if refit:
        view.viewIsometric()
        view.fitAll()
    after = save(view, picture, SIZE)
    box_shadow, lit = pixel_of(view, (36, 5, 0), SIZE), pixel_of(view, (36, -40, 0), SIZE)
    check(what,
          Gui.ActiveDocument.getInEdit() is None and shadows.is_enabled(view) and
          grey(rgb(after, box_shadow)) < 0.25 * grey(rgb(after, lit)),
          shadow=rgb(after, box_shadow), lit=rgb(after, lit))


def sketch_editing(document, view, shadows):
    import Part
    # The sketcher draws the edited sketch's edges in its own colour (View's EditedEdgeColor):
    # pure green here, which nothing else in the scene is.
    App.ParamGet("User parameter:BaseApp/Preferences/View").SetUnsigned("EditedEdgeColor",
                                                                          0x00FF00FF)
    sketch = document.addObject("Sketcher::SketchObject", "Sketch")
    # On the plane's top, in front of the parts: a line from (-30, -70) to (60, -70).
    sketch.addGeometry(Part.LineSegment(App.Vector(-30, -70, 0), App.Vector(60, -70, 0)), False)
    document.recompute()
    Gui.updateGui()
    Gui.ActiveDocument.setEdit("Sketch")
    picture = live("sketch_editing")
    in_edit = Gui.ActiveDocument.getInEdit() is not None
    size = (picture.width(), picture.height())
    # Points along the line, in the camera the sketcher chose; the line is a pixel or two wide,
    # so each point may be a pixel or two from the projection's rounding.
    missing = []
    for step in range(1, 10):
        point = pixel_of(view, (-30 + 9 * step, -70, 0), size)
        if not near(picture, point, green, 3):
            missing.append(point)
    check("sketch in edit mode with shadows on: its lines drawn",
          in_edit and not missing and shadows.is_enabled(view), in_edit=in_edit,
          missing=missing, colours=[rgb(picture, point) for point in missing], size=size)
    leave_edit(view, shadows, "sketch_left", "sketch edit left, shadows still on and cast",
               refit=True)
    document.removeObject("Sketch")
    document.recompute()


def transform_dragger(document, view, shadows):
    # The Placement transform dragger (edit mode 1 of a Part object): FreeCAD's SoFCCSysDragger
    # at the box's placement, the origin, with red, green and blue axes and arrows. Within 80
    # pixels of the origin nothing is strongly green or blue without it (the grey box and
    # plane, their dark edges, the shadows, FreeCAD's blue-grey background, under 150 levels
    # of blue), and the red sphere and its shadow may be there; with it each of the three
    # colours covers at least 20 pixels more there (its axes' shafts alone are 4 pixels wide
    # and about 80 long within that distance).
    def strongly(channel):
        def wanted(colour):
            others = [c for i, c in enumerate(colour) if i != channel]
            return colour[channel] > 150 and all(colour[channel] > c + 80 for c in others)
        return wanted

    before = live("before_dragger")
    size = (before.width(), before.height())
    origin = pixel_of(view, (0, 0, 0), size)
    counts_before = [count(before, origin, 80, strongly(c)) for c in range(3)]
    Gui.ActiveDocument.setEdit("Box", 1)
    during = live("transform_dragger")
    in_edit = Gui.ActiveDocument.getInEdit() is not None
    counts = [count(during, origin, 80, strongly(c)) for c in range(3)]
    check("transform dragger with shadows on: its red, green and blue axes drawn",
          in_edit and all(c >= c0 + 20 for c, c0 in zip(counts, counts_before)) and
          max(counts_before[1:]) < 5,
          in_edit=in_edit, red_green_blue=counts, before=counts_before)
    leave_edit(view, shadows, "dragger_left", "transform edit left, shadows still on and cast")


def per_document(shadows):
    # The settings go with the document (its Meta map, saved in the file): a document shown
    # with the lamp and saved, closed and opened again, has its shadows on again and gets the
    # lamp from enable() with no argument, although the preferences say a directional light;
    # saved with shadows off it opens without them; a new document gets the preferences' light.
    import os
    from macro_common import WORK
    document, view = make_scene("PerDocument")
    shadows.enable(view, light_location=LAMP)
    stored = shadows.stored_settings(document)
    path = os.path.join(WORK, "per_document.FCStd")
    document.saveAs(path)
    shadows.disable(view)
    App.closeDocument(document.Name)
    preferences = shadows.settings_from_preferences()
    document = App.openDocument(path)
    Gui.updateGui()  # the add-on turns them on once FreeCAD has finished opening it
    view = Gui.getDocument(document.Name).ActiveView
    check("per document: a document saved with shadows on opens with them on",
          shadows.is_enabled(view))
    shadows.enable(view)
    light = shadows.group(view).getChild(0)
    location = list(light.location.getValue().getValue()) \
        if light.getTypeId().getName().getString() == "DeepShadowLight" else None
    check("per document: a saved document's lamp comes back, over the preferences",
          preferences["light_type"] == "Directional" and stored.get("light_type") == "Point" and
          location is not None and all(abs(a - b) < 1e-4 for a, b in zip(location, LAMP)),
          preferences=preferences["light_type"], stored=stored, location=location)
    # Saved with them off, it opens without them.
    shadows.disable(view)
    document.save()
    App.closeDocument(document.Name)
    document = App.openDocument(path)
    Gui.updateGui()
    view = Gui.getDocument(document.Name).ActiveView
    check("per document: a document saved with shadows off opens without them",
          not shadows.is_enabled(view), stored=shadows.stored_settings(document))
    App.closeDocument(document.Name)
    document, view = make_scene("Fresh")
    shadows.enable(view)
    kind = shadows.group(view).getChild(0).getTypeId().getName().getString()
    check("per document: a new document takes the preferences' light",
          kind == "DeepShadowDirectionalLight", type=kind)
    shadows.disable(view)
    App.closeDocument(document.Name)


def run():
    import ivshadow.freecad as shadows
    document, view = make_scene("Editing")
    view.getViewer().setEnabledNaviCube(False)
    view.setCornerCrossVisible(False)
    shadows.enable(view, light_direction=LIGHT)
    for step in (point_light, sketch_editing, transform_dragger):
        try:
            step(document, view, shadows)
        except Exception:
            check("%s ran" % step.__name__, False, error=traceback.format_exc())
    shadows.disable(view)
    App.closeDocument("Editing")
    per_document(shadows)


try:
    run()
except Exception:
    check("macro ran", False, error=traceback.format_exc())
finish()
