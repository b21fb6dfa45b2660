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


# live() reads the view once FreeCAD has drawn everything a change asked for: once the picture
# on screen has stayed the same, with no paint of the view, through QUIET seconds and at least
# QUIET_PASSES passes of the event loop. QUIET is more than twice the traced group's refinement
# delay (kRefineDelaySeconds, 0.25 s: a frame traced during a motion is reduced, and refined by
# the frame its alarm asks for a quarter of a second later), so that a refinement still to come
# has been drawn. A fixed wait (it was 1 s, 1.5 s for edit modes) made what was read depend on
# how fast the machine drew: a change may take several frames (opening a sketch turns the
# camera, and the Sketcher workbench's toolbars then resize the view, which is drawn again; a
# traced frame during a motion is reduced, then refined), each pass of the event loop may trace
# one, and a read before the last one shows an earlier frame: read at once after setEdit, the
# screen still held the frame before the edit, in the resized widget's rectangle.
QUIET = 0.6
QUIET_PASSES = 4
# A view still changing after this long fails the check "live view steady" (a picture read
# meanwhile would be any frame of the change).
STEADY_TIMEOUT = 60.0


def _grab(widget):
    from PySide2 import QtCore, QtGui
    origin = widget.mapToGlobal(QtCore.QPoint(0, 0))
    image = QtGui.QGuiApplication.primaryScreen().grabWindow(
        0, origin.x(), origin.y(), widget.width(), widget.height()).toImage()
    return image.convertToFormat(QtGui.QImage.Format_RGB32)


def _paint_counter():
    """An event filter that counts the paint events of the widget it is installed on."""
    from PySide2 import QtCore

    class PaintCounter(QtCore.QObject):
        def __init__(self):
            super().__init__()
            self.paints = 0

        def eventFilter(self, watched, event):  # noqa: N802  (Qt's name)
            if event.type() == QtCore.QEvent.Paint:
                self.paints += 1
            return False

    return PaintCounter()


def live(name):
    """What the screen shows of the active 3D view, read back from the X server (Xvfb holds the
    pixels the GL widget's window got), once it is steady (QUIET above): FreeCAD's paint events,
    the redraws the add-on's sensors schedule, a resize and the traced group's refinement after
    a motion have all been drawn. In physical pixels: the widget's size times its device pixel
    ratio."""
    widget = gl_widget()
    counter = _paint_counter()
    widget.installEventFilter(counter)
    start = time.time()
    try:
        picture = None
        quiet_since, quiet_passes = start, 0
        while True:
            paints = counter.paints
            Gui.updateGui()
            now_picture = _grab(widget)
            now = time.time()
            if counter.paints != paints or picture is None or now_picture != picture:
                quiet_since, quiet_passes = now, 0
            else:
                quiet_passes += 1
            picture = now_picture
            if quiet_passes >= QUIET_PASSES and now - quiet_since >= QUIET:
                break
            if now - start > STEADY_TIMEOUT:
                check("live view steady: " + name, False, seconds=now - start,
                      paints=counter.paints)
                break
            time.sleep(0.05)
    finally:
        widget.removeEventFilter(counter)
    picture.save(os.path.join(WORK, name + ".png"))
    return picture


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
