"""The preferences page (Edit > Preferences > IvShadow), stored in FreeCAD's parameters at
User parameter:BaseApp/Preferences/Mod/IvShadow (ivshadow.freecad.PARAMETERS)."""

from PySide2 import QtGui, QtWidgets

_PRESETS = [("OverTheShoulder", "Over the shoulder"), ("Top", "Top"),
            ("FrontLeft", "Front left")]
_LIGHT_TYPES = [("Directional", "Directional (the sun: parallel shadows)"),
                ("Point", "Point (a lamp near the model: shadows spread from it)")]
_TRANSPARENCIES = [("Exact", "Exact (in depth order per pixel)"),
                   ("FreeCAD", "FreeCAD's own look (Coin's blending)")]
_RENDERERS = [("AUTO", "Automatic (CPU tracer without a GPU, GL on a GPU)"),
              ("RASTER", "GL (fast on a GPU)"), ("TRACER", "CPU tracer (exact)")]


class _ColourButton(QtWidgets.QPushButton):
    def __init__(self):
        super().__init__()
        self.colour = (1.0, 1.0, 1.0)
        self.clicked.connect(self._choose)

    def set_colour(self, colour):
        self.colour = tuple(colour)
        r, g, b = (int(round(c * 255)) for c in self.colour)
        self.setStyleSheet("background-color: rgb(%d, %d, %d)" % (r, g, b))

    def _choose(self):
        chosen = QtWidgets.QColorDialog.getColor(
            QtGui.QColor.fromRgbF(*self.colour), self, "Colour")
        if chosen.isValid():
            self.set_colour((chosen.redF(), chosen.greenF(), chosen.blueF()))


def _choices(items):
    """A combo box of (key, text) items, each text shown and its key the item's data."""
    box = QtWidgets.QComboBox()
    for key, text in items:
        box.addItem(text, key)
    return box


class PreferencesPage:
    """What FreeCAD's preferences dialog asks of a Python page: `form`, loadSettings and
    saveSettings."""

    def __init__(self, parent=None):
        self.form = QtWidgets.QWidget(parent)
        self.form.setWindowTitle("IvShadow")
        layout = QtWidgets.QVBoxLayout(self.form)

        light = QtWidgets.QGroupBox("Light")
        form = QtWidgets.QFormLayout(light)
        self.light_type = _choices(_LIGHT_TYPES)
        form.addRow("Type", self.light_type)
        self.preset = _choices(_PRESETS)
        form.addRow("Direction", self.preset)
        self.light_distance = QtWidgets.QDoubleSpinBox()
        self.light_distance.setRange(0.5, 20.0)
        self.light_distance.setSingleStep(0.25)
        self.light_distance.setSuffix(" x the model")
        self.light_distance.setToolTip("A point light's distance from the model's centre, "
                                       "towards where the direction comes from")
        form.addRow("Point light's distance", self.light_distance)
        self.light_type.currentIndexChanged.connect(self._light_type_changed)
        self.light_color = _ColourButton()
        form.addRow("Colour", self.light_color)
        self.intensity = QtWidgets.QDoubleSpinBox()
        self.intensity.setRange(0.0, 4.0)
        self.intensity.setSingleStep(0.1)
        form.addRow("Intensity", self.intensity)
        self.dragger = QtWidgets.QCheckBox("A dragger in the view that turns the light")
        form.addRow(self.dragger)
        layout.addWidget(light)

        ground = QtWidgets.QGroupBox("Ground")
        form = QtWidgets.QFormLayout(ground)
        self.ground = QtWidgets.QCheckBox("A ground under the model that catches its shadows")
        form.addRow(self.ground)
        self.ground_size = QtWidgets.QDoubleSpinBox()
        self.ground_size.setRange(1.0, 20.0)
        self.ground_size.setSingleStep(0.5)
        self.ground_size.setSuffix(" x the model")
        form.addRow("Size", self.ground_size)
        self.ground_color = _ColourButton()
        form.addRow("Colour", self.ground_color)
        self.ground_transparency = QtWidgets.QSpinBox()
        self.ground_transparency.setRange(0, 100)
        self.ground_transparency.setSuffix(" %")
        form.addRow("Transparency", self.ground_transparency)
        layout.addWidget(ground)

        quality = QtWidgets.QGroupBox("Quality")
        form = QtWidgets.QFormLayout(quality)
        self.renderer = _choices(_RENDERERS)
        form.addRow("Renderer", self.renderer)
        self.transparency = _choices(_TRANSPARENCIES)
        form.addRow("Transparency", self.transparency)
        layout.addWidget(quality)
        layout.addStretch()

    def _light_type_changed(self, *_):
        self.light_distance.setEnabled(self.light_type.currentData() == "Point")

    def loadSettings(self):
        import ivshadow.freecad as shadows
        settings = shadows.settings_from_preferences()
        self.light_type.setCurrentIndex(max(0, self.light_type.findData(settings["light_type"])))
        self.light_distance.setValue(settings["light_distance"])
        self._light_type_changed()
        self.preset.setCurrentIndex(max(0, self.preset.findData(settings["preset"])))
        self.light_color.set_colour(settings["light_color"])
        self.intensity.setValue(settings["intensity"])
        self.ground.setChecked(settings["ground"])
        self.ground_size.setValue(settings["ground_size"])
        self.ground_color.set_colour(settings["ground_color"])
        self.ground_transparency.setValue(settings["ground_transparency"])
        self.renderer.setCurrentIndex(max(0, self.renderer.findData(settings["renderer"])))
        self.transparency.setCurrentIndex(
            max(0, self.transparency.findData(settings["transparency"])))
        self.dragger.setChecked(settings["dragger"])

    def saveSettings(self):
        import ivshadow.freecad as shadows
        settings = {
            "preset": self.preset.currentData(),
            "light_type": self.light_type.currentData(),
            "light_distance": self.light_distance.value(),
            "light_color": self.light_color.colour,
            "intensity": self.intensity.value(),
            "ground": self.ground.isChecked(),
            "ground_size": self.ground_size.value(),
            "ground_color": self.ground_color.colour,
            "ground_transparency": self.ground_transparency.value(),
            "renderer": self.renderer.currentData(),
            "transparency": self.transparency.currentData(),
            "dragger": self.dragger.isChecked(),
        }
        shadows.save_preferences(settings)
        # Views with shadows take the new settings at once.
        shadows.refresh()
