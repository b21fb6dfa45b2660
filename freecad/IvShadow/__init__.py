"""IvShadow: transparent, coloured shadows in FreeCAD's 3D view (docs/FREECAD.md).

FreeCAD 0.20 imports every package of the namespace `freecad` it finds on its sys.path and,
once its GUI is up, runs the package's init_gui.py: that registers the command IvShadow_Toggle,
its toolbar and View menu entry, and the preferences page. The shadows themselves are the
module ivshadow.freecad.
"""
