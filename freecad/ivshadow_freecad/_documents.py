"""The module-level registries (the views with shadows, _states; the observers) and the Gui
document observer (_DocumentObserver) that keeps the groups consistent as FreeCAD deletes
objects and closes documents."""

from ._mesh import _drop_meshes
from ._selection import _SelectionObserver


class _DocumentObserver:
    """Keeps the groups consistent as FreeCAD deletes objects and closes documents."""

    def __init__(self):
        self.watching = False

    def watch(self):
        if not self.watching:
            import FreeCADGui as Gui
            Gui.addDocumentObserver(self)
            Gui.Selection.addObserver(_selection_observer)
            self.watching = True

    def slotDeletedObject(self, view_provider):
        try:
            name = view_provider.Object.Name
            document = view_provider.Object.Document.Name
        except Exception:  # noqa: BLE001  (a view provider without an object)
            name = document = None
        if document is not None:
            _drop_meshes(document, name)
            presel = _selection_observer.preselection
            if presel is not None and presel[0] == document and presel[1] == name:
                _selection_observer.preselection = None
        root = getattr(view_provider, "RootNode", None)
        if root is None:
            return
        for state in _states.values():
            state.forget(root)
            if state.document == document:
                state.highlight.schedule()

    def slotDeletedDocument(self, gui_document):
        name = gui_document.Document.Name
        for key, state in list(_states.items()):
            if state.document == name:
                # The view goes with the document; only the sensors must stop (they would
                # otherwise wake on nodes FreeCAD is about to destroy).
                for sensor in state.sensors():
                    sensor.detach()
                state.highlight.stop()
                del _states[key]
        _drop_meshes(name)
        if _selection_observer.preselection and _selection_observer.preselection[0] == name:
            _selection_observer.preselection = None


# The shadow state (_shadows._Shadows) of each view with shadows, by the address of its scene
# (the SoFCUnifiedSelection node); the observers, added to FreeCAD with the first view's.
_states = {}
_selection_observer = _SelectionObserver(_states)
_observer = _DocumentObserver()
