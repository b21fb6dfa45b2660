"""FreeCAD macro of the add-on's interaction test (run by freecad_test.py inside FreeCAD 0.20's
GUI): the live view against saveImage, picking, selection and pre-selection with shadows on,
deleting and restoring an object, the light's dragger. The scene and the light are those of
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
    Gui.Selection.addSelection(document.Box, "Face6")
    raster_selected = live("live_selected_raster")
    check("selection highlight drawn (face, RASTER)", greenish(rgb(raster_selected, top)),
          face=rgb(raster_selected, top))
    Gui.Selection.clearSelection()
    mouse(widget, "move", logical(widget, top))
    raster_preselected = live("live_preselected_raster")
    check("pre-selection highlight drawn (face, RASTER)", yellowish(rgb(raster_preselected, top)),
          face=rgb(raster_preselected, top))
    mouse(widget, "move", (2, 2))
    shadows.enable(view, light_direction=LIGHT, renderer="AUTO")

    # -- deleting an object and undoing it ------------------------------------------------------
    # The box's shadow on the plane at (36, 5, 0) (shadows_macro.py works the point out).
    shadow_point = pixel_of(view, (36, 5, 0), size)
    lit_point = pixel_of(view, (36, -40, 0), size)
    document.openTransaction("Delete the box")
    document.removeObject("Box")
    document.commitTransaction()
    deleted = save(view, "saved_deleted", size)
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
