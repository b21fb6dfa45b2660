#!/usr/bin/env python3
"""An existing pivy application - read a file, show it in SoQt's examiner viewer - that gains
transparent, coloured shadows with the lines marked "plugin", as examples/soqt_add_shadows.cpp
does in C++: `import ivshadow`, the root wrapped in a TransparentShadowGroup with a
DeepShadowLight, and the viewer's headlight turned off (docs/INTEGRATION.md, "Keep the shadows
dark in a viewer").

    PYTHONPATH=build/python python3 examples/python/soqt_add_shadows.py SCENE.iv \
        [--quit-after-ms N] [--screenshot FILE.png] [--headlight]

--quit-after-ms ends it after N ms; --screenshot then saves what the viewer's window shows
(read back from the X server); --headlight keeps the viewer's headlight on, to see what it
does to the shadows (tests/headlight/headlight_test.py compares the two).
"""
import argparse
import sys

import ivshadow  # noqa: F401  plugin: makes ivshadow's nodes known to pivy's Coin
from pivy import coin
from pivy.gui import soqt


def create(type_name):
    """A node of a type Coin knows by name only (the plugin's), as a file would name it."""
    node = coin.SoType.fromName(coin.SbName(type_name)).createInstance()
    if node is None:
        raise RuntimeError("Coin does not know %s: is ivshadow imported?" % type_name)
    return node


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("--quit-after-ms", type=int)
    parser.add_argument("--screenshot")
    parser.add_argument("--headlight", action="store_true",
                        help="keep the viewer's headlight on (washes the shadows out)")
    options = parser.parse_args()

    window = soqt.SoQt.init(sys.argv[0])
    scene_input = coin.SoInput()
    if not scene_input.openFile(options.scene):
        return 2
    root = coin.SoDB.readAll(scene_input)
    if root is None:
        return 2

    # plugin: wrap the root; put a deep shadow light above the middle of the scene.
    shadows = create("TransparentShadowGroup")
    light = create("DeepShadowLight")
    bounds = coin.SoGetBoundingBoxAction(coin.SbViewportRegion(640, 480))
    bounds.apply(root)
    box = bounds.getBoundingBox()
    low, high = box.getMin().getValue(), box.getMax().getValue()
    centre = box.getCenter().getValue()
    light.getField("location").set("%g %g %g" % (centre[0], centre[1],
                                                 centre[2] + 0.75 * (high[2] - low[2]) + 1.0))
    shadows.addChild(root)
    # The light's location is in world coordinates only after the scene's camera: put before a
    # camera it would be in the camera's coordinates, and move with it.
    cameras = [index for index in range(root.getNumChildren())
               if root.getChild(index).isOfType(coin.SoCamera.getClassTypeId())]
    if cameras:
        root.insertChild(light, cameras[0] + 1)
    else:  # the viewer puts its own camera above the scene graph
        shadows.insertChild(light, 0)

    viewer = soqt.SoQtExaminerViewer(window)
    viewer.setSceneGraph(shadows)
    # plugin: the viewer's headlight lies outside the group, so it lights without casting and
    # would wash the shadows out to mid-grey; the deep shadow light above lights the scene.
    viewer.setHeadlight(options.headlight)
    viewer.show()
    soqt.SoQt.show(window)

    if options.quit_after_ms is not None:
        from PySide2 import QtCore, QtGui

        def quit_():
            if options.screenshot:
                # A frame drawn now, at the window's size: the window manager may have resized
                # the window after the last one was drawn.
                viewer.render()
                widget = viewer.getGLWidget()
                QtGui.QGuiApplication.primaryScreen().grabWindow(
                    widget.winId()).save(options.screenshot)
            soqt.SoQt.exitMainLoop()

        QtCore.QTimer.singleShot(options.quit_after_ms, quit_)
    soqt.SoQt.mainLoop()
    return 0


if __name__ == "__main__":
    sys.exit(main())
