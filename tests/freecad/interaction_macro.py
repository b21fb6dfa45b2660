"""FreeCAD macro of the add-on's interaction test (run by freecad_test.py inside FreeCAD 0.20's
GUI): the live view against saveImage, picking, selection and pre-selection with shadows on,
deleting and restoring an object, the lights' draggers. The scene and the light are those of
shadows_macro.py (macro_common.make_scene); the renderer is AUTO, which on this machine's
llvmpipe traces on the CPU.
"""
import traceback

import numpy  # FreeCAD's own dependency (through python3-matplotlib)

import FreeCAD as App
import FreeCADGui as Gui

from macro_common import (LIGHT, array, check, finish, grey, live, make_scene, pixel_of, rgb,
                          save, size_of)


def mouse(widget, kind, position, button=None):
    """Sends FreeCAD's 3D view a mouse event at `position` (logical pixels of the widget), as a
    user's hand would: through Qt, so FreeCAD's navigation style and SoFCUnifiedSelection handle
    it as they handle real ones."""
    from PySide2 import QtCore, QtGui, QtWidgets
    types = {"move": QtCore.QEvent.MouseMove, "press": QtCore.QEvent.MouseButtonPress,
             "release": QtCore.QEvent.MouseButtonRelease}
    button = QtCore.Qt.LeftButton if button == "left" else QtCore.Qt.NoButton
    pressed = button if kind == "press" else QtCore.Qt.NoButton
    event = QtGui.QMouseEvent(types[kind], QtCore.QPointF(*position), button, pressed,
                              QtCore.Qt.NoModifier)
    QtWidgets.QApplication.sendEvent(widget, event)
    Gui.updateGui()


def disagreeing_pixels(a, b, margin=2):
    """The pixels of `a` or `b` that differ by over 8 levels from every pixel within one of the
    same place in the other picture (the frame's `margin` left out)."""
    first, second = array(a), array(b)
    height, width = first.shape[:2]

    def unmatched(one, other):
        core = one[margin:height - margin, margin:width - margin]
        best = None
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                shifted = other[margin + dy:height - margin + dy, margin + dx:width - margin + dx]
                difference = abs(core - shifted).max(axis=2)
                best = difference if best is None else numpy.minimum(best, difference)
        return best > 8

    return int((unmatched(first, second) | unmatched(second, first)).sum())


def logical(widget, pixel):
    ratio = widget.devicePixelRatioF()
    return pixel[0] / ratio, pixel[1] / ratio


def near(image, pixel, wanted, radius=3):
    """Whether a pixel within `radius` of `pixel` satisfies `wanted`: edges are lines one or two
    pixels wide whose exact pixel the projection's rounding does not tell."""
    for dy in range(-radius, radius + 1):
        for dx in range(-radius, radius + 1):
            if wanted(rgb(image, (pixel[0] + dx, pixel[1] + dy))):
                return True
    return False


def greenish(colour):
    # FreeCAD's selection colour is green (0x1CAD1C): drawn flat on lines, lit on faces, where
    # the light washes it out to (219, 255, 219) on a face lit head on. Grey, the unselected
    # parts' colour, has all three channels within a few levels.
    r, g, b = colour
    return g > r + 25 and g > b + 25


def yellowish(colour):
    # FreeCAD's pre-selection colour is yellow (0xE1E114), lit: (255, 255, 193) on the top face.
    r, g, b = colour
    return min(r, g) > b + 40


def run():
    import ivshadow.freecad as shadows
    from macro_common import gl_widget
    document, view = make_scene("Interaction")
    # The navigation cube and the corner's axis cross are drawn in the live view only, on top
    # of the scene; saveImage has neither.
    view.getViewer().setEnabledNaviCube(False)
    view.setCornerCrossVisible(False)
    widget = gl_widget()

    # -- the live view and saveImage ------------------------------------------------------------
    # A pixel disagrees when no pixel within one of it in the other picture is within 8 levels
    # of it: the window and FreeCAD's framebuffer object rasterise lines a pixel apart (the
    # widget's device pixel ratio scales their width), and 8 levels is the driver's rounding
    # with room to spare. The widget's frame shades the read-back's first row and column: a
    # margin of 2 pixels leaves it out.
    freecad_live = live("live_freecad")
    size = size_of(freecad_live)
    freecad_saved = save(view, "saved_freecad", size)
    baseline = disagreeing_pixels(freecad_live, freecad_saved)

    shadows.enable(view, light_direction=LIGHT)
    shadows_live = live("live_shadows")
    shadows_saved = save(view, "saved_shadows", size)
    disagreement = disagreeing_pixels(shadows_live, shadows_saved)
    # FreeCAD alone disagrees on about a hundred pixels here (the outline of the transparent
    # sphere, whose lines the two contexts draw differently); with shadows the traced picture
    # is the same in both, and at most 0.05 % of the pixels (about 400) may disagree.
    total = size[0] * size[1]
    check("live view and saveImage agree with shadows", disagreement <= 0.0005 * total,
          disagreeing=disagreement, freecad_alone=baseline, pixels=total)

    # The visible edges are drawn whole in the live view (GL draws FreeCAD's lines after the
    # traced picture, depth-tested against it): along the plane's far top edge y = 100, every
    # pixel has a dark line pixel (FreeCAD draws edges near black) within one of it, where the
    # plane and the ground beside it are light grey.
    gaps = []
    for step in range(1, 40):
        point = pixel_of(view, (-50 + 5 * step, 100, 0), size)
        if not near(shadows_live, point, lambda colour: grey(colour) < 100, radius=1):
            gaps.append(point)
    check("live view: visible edges whole", not gaps, gaps=gaps)

    # No hidden edge through the box in the live view (AUTO traces here): the back vertical
    # edge x = 0, y = 30 is behind the box's top face; at its middle the top face looks as it
    # does six pixels to either side (an edge drawn black would be over 60 levels darker).
    edge = pixel_of(view, (0, 30, 20), size)
    sides = [rgb(shadows_live, (edge[0] - 6, edge[1])), rgb(shadows_live, (edge[0] + 6, edge[1]))]
    check("live view: no hidden edge through the box",
          grey(rgb(shadows_live, edge)) > min(grey(side) for side in sides) - 25,
          edge=rgb(shadows_live, edge), sides=sides)

    # -- pre-selection and selection by the mouse, with shadows on ------------------------------
    top = pixel_of(view, (15, 15, 30), size)  # the middle of the box's top face (Face6)
    mouse(widget, "move", logical(widget, top))
    preselection = Gui.Selection.getPreselection()
    check("pre-selection under the mouse",
          preselection.ObjectName == "Box" and preselection.SubElementNames == ("Face6",),
          object=preselection.ObjectName, elements=list(preselection.SubElementNames))
    mouse(widget, "press", logical(widget, top), "left")
    mouse(widget, "release", logical(widget, top), "left")
    selected = [(entry.ObjectName, list(entry.SubElementNames))
                for entry in Gui.Selection.getSelectionEx()]
    check("selection by a click", selected == [("Box", ["Face6"])], selected=selected)
    # Clearing a selection applies FreeCAD's selection action to the whole scene, the add-on's
    # nodes included (it crashed FreeCAD while they held a transform separator).
    Gui.Selection.clearSelection()
    Gui.Selection.clearPreselection()
    check("selection cleared with shadows on", not Gui.Selection.getSelectionEx())

    # The highlight is drawn: the whole box selected turns its visible edges green (GL draws
    # FreeCAD's lines after the traced picture); the front vertical edge x = 30, y = 0.
    front_edge = pixel_of(view, (30, 0, 15), size)
    Gui.Selection.addSelection(document.Box)
    selected_picture = live("live_selected")
    check("selection highlight drawn (edges)",
          near(selected_picture, front_edge, greenish) and not near(shadows_live, front_edge,
                                                                     greenish),
          at=front_edge)
    Gui.Selection.clearSelection()

    # With renderer RASTER GL draws the faces too, FreeCAD's highlight of a face with them:
    # the selected top face turns green, the pre-selected one yellow.
    shadows.enable(view, light_direction=LIGHT, renderer="RASTER")
    # The box's two visible sides, at their middles: x = 30 and y = 0.
    visible_sides = [pixel_of(view, (30, 15, 15), size), pixel_of(view, (15, 0, 15), size)]
    raster_plain = live("live_unselected_raster")
    Gui.Selection.addSelection(document.Box, "Face6")
    raster_selected = live("live_selected_raster")
    check("selection highlight drawn (face, RASTER)", greenish(rgb(raster_selected, top)),
          face=rgb(raster_selected, top))
    # Issue 38: FreeCAD draws the selected face with the selection colour as its emissive colour,
    # then the box's other faces in the same node; the group's programs kept the green for
    # them (Mesa, nodes/MaterialSyncElement.h), and the sides read (36, 214, 36). They must
    # look as they do with nothing selected: the same picture drawn again, within the 3 levels
    # the test allows any picture drawn twice.
    def unchanged(picture, pixels):
        return all(max(abs(a - b) for a, b in zip(rgb(picture, p), rgb(raster_plain, p))) <= 3
                   for p in pixels)

    check("selection highlight only on the selected face (RASTER)",
          unchanged(raster_selected, visible_sides) and
          not any(greenish(rgb(raster_selected, p)) for p in visible_sides),
          sides=[rgb(raster_selected, p) for p in visible_sides],
          unselected=[rgb(raster_plain, p) for p in visible_sides])
    Gui.Selection.clearSelection()
    # A face the view does not show (Face1, x = 0, behind the box) selected: FreeCAD draws it
    # green behind the others, and every visible face keeps its colour.
    Gui.Selection.addSelection(document.Box, "Face1")
    raster_hidden = live("live_hidden_face_selected_raster")
    check("a hidden face selected leaves the visible ones unchanged (RASTER)",
          unchanged(raster_hidden, visible_sides + [top]),
          faces=[rgb(raster_hidden, p) for p in visible_sides + [top]],
          unselected=[rgb(raster_plain, p) for p in visible_sides + [top]])
    Gui.Selection.clearSelection()
    mouse(widget, "move", logical(widget, top))
    raster_preselected = live("live_preselected_raster")
    check("pre-selection highlight drawn (face, RASTER)", yellowish(rgb(raster_preselected, top)),
          face=rgb(raster_preselected, top))
    mouse(widget, "move", (2, 2))
    shadows.enable(view, light_direction=LIGHT, renderer="AUTO")

    # With AUTO, traced here, FreeCAD's highlight of faces (drawn in SoBrepFaceSet::GLRender,
    # which the tracer does not run) comes from the add-on's overlay: the selected face green,
    # the pre-selected one yellow, at every one of five points inside the top face (Face6), in
    # the live view and in saveImage; clearing gives the picture back.
    face_points = [pixel_of(view, point, size) for point in
                   ((15, 15, 30), (6, 6, 30), (24, 6, 30), (6, 24, 30), (24, 24, 30))]
    Gui.Selection.clearSelection()
    Gui.Selection.clearPreselection()
    plain_live = live("live_unhighlighted_traced")
    plain_saved = save(view, "saved_unhighlighted_traced", size)
    colours = [rgb(plain_live, point) for point in face_points]
    check("traced face not highlighted before selection",
          not any(greenish(c) or yellowish(c) for c in colours), face=colours)
    Gui.Selection.addSelection(document.Box, "Face6")
    traced_selected = live("live_selected_traced")
    saved_selected = save(view, "saved_selected_traced", size)
    colours = [rgb(traced_selected, point) for point in face_points]
    saved_colours = [rgb(saved_selected, point) for point in face_points]
    check("selection highlight drawn (face, traced)",
          all(greenish(c) for c in colours + saved_colours), live=colours, saved=saved_colours,
          raster=rgb(raster_selected, top))
    # The other faces keep their colour (the front side x = 30 at its middle).
    side = pixel_of(view, (30, 15, 15), size)
    check("selection highlight only on the selected face (traced)",
          not greenish(rgb(traced_selected, side)), side=rgb(traced_selected, side))
    # Pre-selection over the selected face: the overlay is unpickable, so the mouse still finds
    # the face, and FreeCAD's pre-selection colour wins, as FreeCAD draws it last.
    mouse(widget, "move", logical(widget, top))
    preselection = Gui.Selection.getPreselection()
    traced_preselected = live("live_preselected_traced")
    colours = [rgb(traced_preselected, point) for point in face_points]
    check("pre-selection highlight drawn (face, traced)",
          preselection.ObjectName == "Box" and preselection.SubElementNames == ("Face6",) and
          all(yellowish(c) for c in colours), live=colours,
          raster=rgb(raster_preselected, top), elements=list(preselection.SubElementNames))
    mouse(widget, "move", (2, 2))
    back_to_selection = live("live_preselection_gone_traced")
    colours = [rgb(back_to_selection, point) for point in face_points]
    check("pre-selection highlight goes with the mouse (traced)",
          all(greenish(c) for c in colours), live=colours)
    # The selected face follows a recompute: the box 40 high, its top face is green at z = 40.
    document.Box.Height = 40
    document.recompute()
    taller = live("live_selected_taller_traced")
    taller_points = [pixel_of(view, (x, y, 40), size) for x, y, _ in
                     ((15, 15, 30), (6, 6, 30), (24, 24, 30))]
    colours = [rgb(taller, point) for point in taller_points]
    check("selection highlight follows a recompute (traced)", all(greenish(c) for c in colours),
          live=colours)
    document.Box.Height = 30
    document.recompute()
    # The whole box selected: every visible face green, the side too.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(document.Box)
    whole = live("live_whole_selected_traced")
    check("whole object selected: all its faces highlighted (traced)",
          greenish(rgb(whole, side)) and greenish(rgb(whole, top)),
          side=rgb(whole, side), top=rgb(whole, top))
    # Cleared: the picture is the unhighlighted one again. saveImage is traced at full size
    # both times: at most 3 levels anywhere; the live view may still refine (movingResolution),
    # so it is held to 3 levels on 99.9 % of the pixels.
    Gui.Selection.clearSelection()
    Gui.Selection.clearPreselection()
    cleared_saved = save(view, "saved_cleared_traced", size)
    cleared_live = live("live_cleared_traced")
    saved_difference = int(abs(array(cleared_saved) - array(plain_saved)).max())
    live_changed = int((abs(array(cleared_live) - array(plain_live)).max(axis=2) > 3).sum())
    check("clearing the selection restores the traced picture",
          saved_difference <= 3 and live_changed <= 0.001 * size[0] * size[1],
          saveimage_largest_difference=saved_difference, live_pixels_over_3=live_changed)

    # -- deleting an object and undoing it ------------------------------------------------------
    # The box's shadow on the plane at (36, 5, 0) (shadows_macro.py works the point out).
    shadow_point = pixel_of(view, (36, 5, 0), size)
    lit_point = pixel_of(view, (36, -40, 0), size)
    # Deleted while selected and pre-selected: its highlight goes with it (no green or yellow
    # pixel left), and FreeCAD does not crash.
    Gui.Selection.addSelection(document.Box, "Face6")
    mouse(widget, "move", logical(widget, top))
    document.openTransaction("Delete the box")
    document.removeObject("Box")
    document.commitTransaction()
    deleted = save(view, "saved_deleted", size)
    pixels = array(deleted)
    red, green, blue = pixels[:, :, 0], pixels[:, :, 1], pixels[:, :, 2]
    highlighted = int(((green > red + 25) & (green > blue + 25)).sum() +
                      ((numpy.minimum(red, green) > blue + 40)).sum())
    check("a deleted selected box leaves no highlight", highlighted == 0, pixels=highlighted)
    mouse(widget, "move", (2, 2))
    check("deleted box casts no shadow",
          grey(rgb(deleted, shadow_point)) > 0.8 * grey(rgb(deleted, lit_point)),
          shadow=rgb(deleted, shadow_point), lit=rgb(deleted, lit_point))
    # Undo gives the box a new view provider, whose root FreeCAD appends to its selection node.
    document.undo()
    restored = save(view, "saved_restored", size)
    check("undone deletion casts again",
          document.getObject("Box") is not None and
          grey(rgb(restored, shadow_point)) < 0.25 * grey(rgb(restored, lit_point)),
          shadow=rgb(restored, shadow_point), lit=rgb(restored, lit_point))

    # -- the light's dragger ----------------------------------------------------------------
    from pivy import coin
    shadows.enable(view, light_direction=LIGHT, dragger=True)
    search = coin.SoSearchAction()
    search.setName(coin.SbName("IvShadowLightDragger"))
    search.apply(view.getSceneGraph())
    path = search.getPath()
    dragger = path.getTail().getChild(1) if path is not None else None
    length = sum(c * c for c in LIGHT) ** 0.5
    arrow = dragger.rotation.getValue().multVec(coin.SbVec3f(0, 0, -1)).getValue() \
        if dragger is not None else None
    # The arrow is the light's direction, to float precision.
    check("dragger shows the light's direction",
          arrow is not None and all(abs(a - c / length) < 1e-4 for a, c in zip(arrow, LIGHT)),
          arrow=list(arrow) if arrow else None)
    # Turned straight down, as a drag writes its rotation: the light follows, so the box's
    # shadow leaves (36, 5, 0) (beside the box, lit from above) and the sphere's falls right
    # under it at (90, 0, 0), red.
    dragger.rotation.setValue(coin.SbRotation())
    turned = save(view, "saved_dragger_turned", size)
    beside_box = rgb(turned, shadow_point)
    under_sphere = rgb(turned, pixel_of(view, (90, 0, 0), size))
    check("turning the dragger turns the light",
          grey(beside_box) > 0.8 * grey(rgb(turned, lit_point)) and
          under_sphere[0] > 1.5 * max(under_sphere[1:]),
          beside_box=beside_box, under_sphere=under_sphere)
    shadows.enable(view, dragger=False)
    search.apply(view.getSceneGraph())
    check("dragger removed when turned off", search.getPath() is None)

    # A point light's dragger (Coin's SoPointLightDragger, after a scale that sizes it): its
    # place, the scale times its translation, is the lamp's. Moved as a drag writes its
    # translation, to right above the box's centre, (15, 15, 120): the lamp follows, and so
    # does the box's shadow. From the geometry: the segment from the plane point (33, 15, 0) to
    # the lamp meets the box's top z = 30 at x = 28.5, inside it (in shadow); the one from
    # (60, 15, 0) passes x = 30 at height 80, above the box, and no part is near it (lit).
    shadows.enable(view, light_location=(15, 80, 80), dragger=True)
    search.setName(coin.SbName("IvShadowLampDragger"))
    search.apply(view.getSceneGraph())
    path = search.getPath()
    root = path.getTail() if path is not None else None
    scale = root.getChild(0).scaleFactor.getValue()[0] if root is not None else None
    lamp_dragger = root.getChild(1) if root is not None else None
    place = [c * scale for c in lamp_dragger.translation.getValue().getValue()] \
        if lamp_dragger is not None else None
    # Float precision at the lamp's distance, about 100.
    check("point light's dragger at the lamp",
          place is not None and all(abs(a - b) < 1e-3 for a, b in zip(place, (15, 80, 80))),
          place=place)
    lamp_dragger.translation.setValue(coin.SbVec3f(15 / scale, 15 / scale, 120 / scale))
    lamp = shadows.group(view).getChild(0).location.getValue().getValue()
    moved = save(view, "saved_lamp_dragged", size)
    in_shadow = rgb(moved, pixel_of(view, (33, 15, 0), size))
    lit = rgb(moved, pixel_of(view, (60, 15, 0), size))
    stored = shadows.stored_settings(document).get("light_location")
    # The shadow under a quarter of the lit point, as in the other shadow checks.
    check("moving the point light's dragger moves the lamp and its shadow",
          all(abs(a - b) < 1e-3 for a, b in zip(lamp, (15, 15, 120))) and
          grey(in_shadow) < 0.25 * grey(lit) and
          stored is not None and all(abs(a - b) < 1e-3 for a, b in zip(stored, (15, 15, 120))),
          lamp=list(lamp), shadow=in_shadow, lit=lit, stored=stored)
    shadows.enable(view, light_direction=LIGHT, dragger=False)
    search.apply(view.getSceneGraph())
    check("point light's dragger removed when turned off", search.getPath() is None)

    # -- transparency: exact or FreeCAD's own look, from the preferences -------------------
    saved = shadows.settings_from_preferences()
    shadows.save_preferences(dict(saved, transparency="FreeCAD"))
    shadows.refresh()
    freecad_look = str(shadows.group(view).transparency.get())
    shadows.save_preferences(saved)
    shadows.refresh()
    exact_look = str(shadows.group(view).transparency.get())
    check("transparency preference: FreeCAD's look is Coin's blending, exact is peeling",
          freecad_look == "COIN_BLENDING" and exact_look == "PEELED",
          freecad_look=freecad_look, exact_look=exact_look)

    shadows.disable(view)
    App.closeDocument("Interaction")


try:
    run()
except Exception:
    check("macro ran", False, error=traceback.format_exc())
finish()
