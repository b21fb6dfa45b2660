"""What the FreeCAD macros of the add-on's tests share (shadows_macro.py, interaction_macro.py):
the JSON of checks, the test scene, FreeCAD's camera projection and pictures of the live view
and of saveImage. Imported by the macros, which FreeCAD imports as modules from this folder."""
import json
import os
import time

import FreeCAD as App
import FreeCADGui as Gui

RESULT = os.environ["IVSHADOW_FREECAD_RESULT"]
WORK = os.environ["IVSHADOW_FREECAD_WORK"]
PREFIX = os.environ["IVSHADOW_FREECAD_PREFIX"]

# The direction the test's light travels: down and towards the isometric camera's side, so that
# the shadows fall where the camera sees them.
LIGHT = (0.4, -0.3, -1.0)

checks = []


def check(name, passed, **measured):
    checks.append({"name": name, "passed": bool(passed), "measured": measured})
    # Written after every check: a hang or crash later still leaves what was measured.
    with open(RESULT, "w") as f:
        json.dump(checks, f, indent=1)


def finish():
    check("macro finished", True)
    os._exit(0)


def make_scene(name):
    """A plane (a 200 x 200 x 1 box whose top is z = 0), a grey 30 mm box at the origin and a red
    sphere of radius 15, 50 % transparent, centred 50 mm above the plane, in FreeCAD's
    isometric camera fitted to them. Returns (document, view)."""
    document = App.newDocument(name)
    plane = document.addObject("Part::Box", "Plane")
    plane.Length, plane.Width, plane.Height = 200, 200, 1
    plane.Placement.Base = App.Vector(-50, -100, -1)
    box = document.addObject("Part::Box", "Box")
    box.Length = box.Width = box.Height = 30
    sphere = document.addObject("Part::Sphere", "Sphere")
    sphere.Radius = 15
    sphere.Placement.Base = App.Vector(90, 0, 50)
    document.recompute()
    sphere.ViewObject.ShapeColor = (1.0, 0.0, 0.0)
    sphere.ViewObject.Transparency = 50
    view = Gui.ActiveDocument.ActiveView
    view.setAnimationEnabled(False)
    view.viewIsometric()
    view.fitAll()
    Gui.updateGui()
    return document, view


def pixel_of(view, point, size):
    """The pixel (column, row from the top) of a document point in a picture of `size` (width,
    height) taken with the view's camera at that aspect ratio (saveImage, or the live view)."""
    from pivy import coin
    width, height = size
    camera = view.getCameraNode()
    volume = camera.getViewVolume(width / height)
    screen = volume.projectToScreen(coin.SbVec3f(*point)).getValue()
    return int(screen[0] * width), int((1.0 - screen[1]) * height)


def load(path):
    from PySide2 import QtGui
    return QtGui.QImage(path).convertToFormat(QtGui.QImage.Format_RGB32)


def save(view, name, size):
    path = os.path.join(WORK, name + ".png")
    Gui.updateGui()  # sensors (the add-on's among them) run before the picture
    view.saveImage(path, size[0], size[1], "Current")
    return load(path)


def gl_widget():
    """The QOpenGLWidget that shows the 3D view on screen: the viewport of FreeCAD's
    QuarterWidget (a QGraphicsView), which draws the scene in its paint event. The tests show
    one document at a time, so one is visible."""
    from PySide2 import QtWidgets
    return [widget for widget in Gui.getMainWindow().findChildren(QtWidgets.QWidget)
            if widget.metaObject().className() == "QOpenGLWidget" and widget.isVisible()][0]


def live(name, settle=1.0):
    """What the screen shows of the active 3D view, read back from the X server (Xvfb holds the
    pixels the GL widget's window got): FreeCAD's paint events, the redraws the add-on's
    sensors schedule and the traced group's refinement a quarter of a second after a motion
    all run first, for `settle` seconds. In physical pixels: the widget's size times its
    device pixel ratio."""
    from PySide2 import QtCore, QtGui
    end = time.time() + settle
    while time.time() < end:
        Gui.updateGui()
        time.sleep(0.05)
    widget = gl_widget()
    origin = widget.mapToGlobal(QtCore.QPoint(0, 0))
    image = QtGui.QGuiApplication.primaryScreen().grabWindow(
        0, origin.x(), origin.y(), widget.width(), widget.height()).toImage()
    image = image.convertToFormat(QtGui.QImage.Format_RGB32)
    image.save(os.path.join(WORK, name + ".png"))
    return image


def size_of(image):
    return image.width(), image.height()


def rgb(image, pixel):
    value = image.pixel(pixel[0], pixel[1])
    return (value >> 16) & 0xFF, (value >> 8) & 0xFF, value & 0xFF


def grey(colour):
    return sum(colour) / 3.0


def array(image):
    """The picture as a numpy array of rows x columns x (r, g, b), ints."""
    import numpy
    data = numpy.frombuffer(image.constBits(), dtype=numpy.uint8,
                            count=image.height() * image.bytesPerLine())
    data = data.reshape(image.height(), image.bytesPerLine() // 4, 4)[:, :image.width(), :]
    # Format_RGB32 is 0xffRRGGBB: bytes b, g, r, 255 in memory on a little-endian machine.
    return data[:, :, 2::-1].astype(int)
