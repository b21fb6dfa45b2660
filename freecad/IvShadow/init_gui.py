"""The add-on's GUI, run by FreeCAD once its main window is up: the command IvShadow_Toggle,
a toolbar shown in every workbench, an entry in the View menu, the preferences page, and
shadows turned on again in a document saved with them on."""

import json
import os

import FreeCAD as App
import FreeCADGui as Gui

_ICON = os.path.join(os.path.dirname(__file__), "IvShadow.svg")
_TOOLBARS = "User parameter:BaseApp/Workbench/Global/Toolbar"
_PARAMETERS = "User parameter:BaseApp/Preferences/Mod/IvShadow"


def _shadows():
    # Imported when first used: it loads the plugin into the process, which FreeCAD users
    # who never press the button need not pay for at start.
    import ivshadow.freecad
    return ivshadow.freecad


def _active_view():
    document = Gui.ActiveDocument
    view = document.ActiveView if document else None
    return view if view is not None and hasattr(view, "getSceneGraph") else None


class ToggleCommand:
    """Shadows on or off in the active 3D view, with the preferences' settings."""

    def GetResources(self):
        return {"Pixmap": _ICON,
                "MenuText": "Transparent shadows",
                "ToolTip": "Shadows in the active 3D view, tinted and partial where parts are "
                           "transparent, on a ground under the model (ivshadow)"}

    def IsActive(self):
        return _active_view() is not None

    def Activated(self):
        view = _active_view()
        shadows = _shadows()
        if shadows.is_enabled(view):
            shadows.disable(view)
        else:
            shadows.enable(view)


def _add_global_toolbar():
    # A toolbar in FreeCAD's "Global" set is shown in every workbench; the entry's value is the
    # module FreeCAD imports to find the command if it does not know it yet. Added once: a user
    # who removes it (Tools > Customize) keeps it removed.
    settings = App.ParamGet(_PARAMETERS)
    if settings.GetBool("ToolbarAdded", False):
        return
    toolbar = App.ParamGet(_TOOLBARS + "/IvShadow")
    toolbar.SetString("Name", "IvShadow")
    toolbar.SetBool("Active", True)
    toolbar.SetString("IvShadow_Toggle", "freecad.IvShadow.init_gui")
    settings.SetBool("ToolbarAdded", True)


def _add_to_view_menu(*_):
    # Each workbench sets up the menus again; the entry goes back in after every switch.
    from PySide2 import QtGui, QtWidgets
    window = Gui.getMainWindow()
    for menu in window.menuBar().findChildren(QtWidgets.QMenu):
        if menu.objectName() != "&View":
            continue
        if any(action.objectName() == "IvShadow_Toggle" for action in menu.actions()):
            return
        action = QtWidgets.QAction(QtGui.QIcon(_ICON), "Transparent shadows", menu)
        action.setObjectName("IvShadow_Toggle")
        action.setToolTip(ToggleCommand().GetResources()["ToolTip"])
        action.triggered.connect(lambda: Gui.runCommand("IvShadow_Toggle"))
        menu.addSeparator()
        menu.addAction(action)
        return


class _ReopenObserver:
    """Shadows on again in a document that had them on when it was saved (the key "enabled"
    of its settings, which ivshadow.freecad keeps in the document's Meta map under "IvShadow"):
    FreeCAD gives an opened document back its camera and display modes, and a user who saved
    a model with its shadows expects them back as well. Reading the Meta map needs nothing of
    the plugin; it is loaded only for such a document."""

    def slotCreatedDocument(self, document):
        # FreeCAD 0.20's observers are told of a document when it is made, before an opened
        # one is read (there is no slot for the end of that): the Meta map is looked at once
        # FreeCAD has finished opening it and made its 3D view.
        from PySide2 import QtCore
        QtCore.QTimer.singleShot(0, lambda name=document.Name: _show_shadows(name))


def _show_shadows(document_name):
    try:
        document = App.getDocument(document_name)
        on = json.loads(document.Meta.get("IvShadow", "{}")).get("enabled") is True
        view = Gui.getDocument(document_name).ActiveView
    except Exception:  # closed meanwhile (FreeCAD raises on an unknown name), or no settings
        return
    if on and view is not None and hasattr(view, "getSceneGraph"):
        shadows = _shadows()
        if not shadows.is_enabled(view):
            shadows.enable(view)


_reopen_observer = _ReopenObserver()
App.addDocumentObserver(_reopen_observer)
Gui.addCommand("IvShadow_Toggle", ToggleCommand())
_add_global_toolbar()
try:
    from freecad.IvShadow import preferences
    Gui.addPreferencePage(preferences.PreferencesPage, "IvShadow")
    Gui.getMainWindow().workbenchActivated.connect(_add_to_view_menu)
    _add_to_view_menu()
except Exception as error:  # the command works without the page and menu entry
    App.Console.PrintWarning("IvShadow: %s\n" % error)
