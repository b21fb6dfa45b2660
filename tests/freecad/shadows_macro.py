"""FreeCAD macro of the add-on's test (run by freecad_test.py inside FreeCAD 0.20's GUI).

Writes RESULT (JSON: checks passed and failed, with the measured values) and exits. Reads the
environment: IVSHADOW_FREECAD_RESULT (the JSON file), IVSHADOW_FREECAD_WORK (pictures),
IVSHADOW_FREECAD_PREFIX (the scratch install the add-on must have been loaded from).

The scene: a plane (a 200 x 200 x 1 box whose top is z = 0), a grey 30 mm box at the origin
and a red sphere of radius 15, 50 % transparent, centred 50 mm above the plane; FreeCAD's
isometric camera. The light travels along L = (0.4, -0.3, -1): down and towards the camera's
side, so that the shadows fall where the camera sees them. Where a shadow is is worked out
here from the geometry (a point of the plane is in shadow when the ray from it towards the
light, along -L, meets the part), and its pixel from FreeCAD's camera (its view volume
projects the point), never from the picture itself.
"""
import os
import traceback

import FreeCAD as App
import FreeCADGui as Gui

from macro_common import (LIGHT, PREFIX, array, check, finish, grey, make_scene, rgb, save as save_as,
                          pixel_of as pixel_in)

WIDTH, HEIGHT = 640, 480


def pixel_of(view, point):
    return pixel_in(view, point, (WIDTH, HEIGHT))


def save(view, name):
    return save_as(view, name, (WIDTH, HEIGHT))


def largest_difference(a, b):
    """The largest difference of any channel of any pixel."""
    return int(abs(array(a) - array(b)).max())


def run():
    # Loading: FreeCAD found the add-on at start (its init_gui registered the command) and the
    # module from the scratch install, whose plugin it loaded by the path recorded there.
    check("command registered at start", "IvShadow_Toggle" in Gui.listCommands())
    import ivshadow
    import ivshadow.freecad as shadows
    check("module from the install", ivshadow.__file__.startswith(PREFIX),
          module=ivshadow.__file__)
    check("plugin from the install", ivshadow.library().startswith(PREFIX) and
          os.path.exists(ivshadow.library()) and "LD_LIBRARY_PATH" not in os.environ,
          library=ivshadow.library())

    document, view = make_scene("Shadows")

    before = save(view, "freecad_before")
    check("disabled at first", not shadows.is_enabled(view))

    shadows.enable(view, light_direction=LIGHT)
    check("enabled", shadows.is_enabled(view))
    on = save(view, "freecad_shadows")
    # What AUTO chose: under Xvfb GL is Mesa's llvmpipe, a software rasteriser, where the group
    # traces (nodes/AutoTracerChoice.h).
    check("renderer in use (AUTO)", shadows.renderer_in_use(view) == "TRACER",
          renderer=shadows.renderer_in_use(view))

    # Points of the plane's top (z = 0), from the geometry:
    # - box shadow: from (36, 5, 0) along -L = (-0.4, 0.3, 1) the ray reaches x = 30 at
    #   height 15, at y = 9.5: inside the box (0..30 on each axis);
    # - sphere shadow: the sphere's centre (90, 0, 50) carried along L down to z = 0;
    # - lit: (36, -40, 0): its ray towards the light reaches y = 0 (the box's near side) only
    #   at height 133, far above the box, and passes 70 mm from the sphere at its height;
    # and the ray from each of these three to the isometric camera (along (1, -1, 1)) moves away
    # from every part, so none is hidden.
    box_shadow = pixel_of(view, (36, 5, 0))
    sphere_shadow = pixel_of(view, (90 + 0.4 * 50, 0 - 0.3 * 50, 0))
    lit = pixel_of(view, (36, -40, 0))
    lit_rgb = rgb(on, lit)
    box_rgb = rgb(on, box_shadow)
    sphere_rgb = rgb(on, sphere_shadow)
    # Lit plane: FreeCAD's grey (0.8) times cos(angle to the light) = 0.89: about 180 levels.
    check("plane lit", grey(lit_rgb) > 120, lit=lit_rgb)
    # The box's shadow keeps only the ambient light (Coin's ambient intensity 0.2 times
    # FreeCAD's ambient colour 0.2, a few levels): under a quarter of the lit plane. With
    # FreeCAD's headlight still on it stays mid-grey, about half of the lit plane.
    check("box shadow dark", grey(box_rgb) < 0.25 * grey(lit_rgb), shadow=box_rgb, lit=lit_rgb)
    # Light through 50 % red glass: red passes (a partial shadow in red), green and blue are
    # absorbed: red well above green and blue, green and blue far below the lit plane's, and
    # the red channel well above the opaque box's shadow.
    check("sphere shadow red and partial",
          sphere_rgb[0] > 1.5 * max(sphere_rgb[1], sphere_rgb[2]) and
          max(sphere_rgb[1], sphere_rgb[2]) < 0.6 * lit_rgb[1] and
          sphere_rgb[0] > box_rgb[0] + 30,
          shadow=sphere_rgb, lit=lit_rgb, box_shadow=box_rgb)

    # No hidden edge through the box: the back vertical edge x = 0, y = 30 is hidden behind
    # the box's top face; at its middle's pixel the top face must look as it does six pixels to
    # either side (FreeCAD draws edges black, a line would be over 60 levels darker).
    edge = pixel_of(view, (0, 30, 20))
    sides = [rgb(on, (edge[0] - 6, edge[1])), rgb(on, (edge[0] + 6, edge[1]))]
    check("no hidden edge through the box",
          grey(rgb(on, edge)) > min(grey(side) for side in sides) - 25,
          edge=rgb(on, edge), sides=sides)

    # The same check with renderer RASTER (GL draws the children): the check itself finds no
    # edge where none is drawn.
    shadows.enable(view, light_direction=LIGHT, renderer="RASTER")
    raster = save(view, "freecad_shadows_raster")
    check("renderer in use (RASTER)", shadows.renderer_in_use(view) == "RASTER",
          renderer=shadows.renderer_in_use(view))
    sides = [rgb(raster, (edge[0] - 6, edge[1])), rgb(raster, (edge[0] + 6, edge[1]))]
    check("no hidden edge through the box (RASTER)",
          grey(rgb(raster, edge)) > min(grey(side) for side in sides) - 25,
          edge=rgb(raster, edge), sides=sides)
    shadows.enable(view, light_direction=LIGHT, renderer="AUTO")

    # An object created after enable() casts: a cylinder of radius 8 and height 40 at
    # (60, -70); (68, -76, 0) is 10 mm from its axis, outside it, and its ray towards the
    # light meets the axis at height 20.
    cast = pixel_of(view, (68, -76, 0))
    lit_before = rgb(on, cast)
    cylinder = document.addObject("Part::Cylinder", "Cylinder")
    cylinder.Radius, cylinder.Height = 8, 40
    cylinder.Placement.Base = App.Vector(60, -70, 0)
    document.recompute()
    added = save(view, "freecad_added")
    check("object added afterwards casts",
          grey(rgb(added, cast)) < 0.25 * grey(lit_before),
          before=lit_before, after=rgb(added, cast))

    # Removing it: no crash, and its shadow goes with it (its root left the group).
    document.removeObject("Cylinder")
    removed = save(view, "freecad_removed")
    check("removed object's shadow gone",
          abs(grey(rgb(removed, cast)) - grey(lit_before)) < 10,
          before=lit_before, after=rgb(removed, cast))

    # From below, the ground hides (the plane, a part, still shows): the picture matches
    # FreeCAD's own from below at (170, -40, 0), beyond the plane (x <= 150) but on the ground.
    shadows.disable(view)
    view.viewBottom()
    bottom_before = save(view, "freecad_bottom_before")
    shadows.enable(view, light_direction=LIGHT)
    bottom = save(view, "freecad_bottom")
    beyond = pixel_of(view, (170, -40, 0))
    check("ground hidden from below",
          max(abs(a - b) for a, b in zip(rgb(bottom, beyond), rgb(bottom_before, beyond))) <= 3,
          shadows=rgb(bottom, beyond), freecad=rgb(bottom_before, beyond))
    view.viewIsometric()
    view.fitAll()

    # The command toggles the active view, and FreeCAD shows it in a toolbar of its own and in
    # the View menu.
    from PySide2 import QtWidgets
    window = Gui.getMainWindow()
    check("toolbar", any(bar.objectName() == "IvShadow" and bar.isVisible()
                         for bar in window.findChildren(QtWidgets.QToolBar)))
    check("View menu entry", any(action.objectName() == "IvShadow_Toggle"
                                 for menu in window.findChildren(QtWidgets.QMenu)
                                 if menu.objectName() == "&View" for action in menu.actions()))
    Gui.runCommand("IvShadow_Toggle")
    off_by_command = not shadows.is_enabled(view)
    Gui.runCommand("IvShadow_Toggle")
    check("command toggles", off_by_command and shadows.is_enabled(view))

    shadows.disable(view)
    check("disabled", not shadows.is_enabled(view))
    check("no renderer in use without shadows", shadows.renderer_in_use(view) is None,
          renderer=shadows.renderer_in_use(view))
    after = save(view, "freecad_after")
    # The same GL drawing of the same scene graph as before enable(): 3 levels allow for
    # nothing but rounding in the driver.
    worst = largest_difference(before, after)
    check("disable restores FreeCAD's picture", worst <= 3, largest_difference=worst)

    # Closing a document whose view has shadows.
    shadows.enable(view, light_direction=LIGHT)
    App.closeDocument("Shadows")
    Gui.updateGui()
    check("document closed with shadows on", True)


try:
    run()
except Exception:
    check("macro ran", False, error=traceback.format_exc())
finish()
