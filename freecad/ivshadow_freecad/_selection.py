"""FreeCAD's selection and pre-selection, heard by an observer (_SelectionObserver) that
updates the highlight overlay (_highlight.py) of the views with shadows."""


class _SelectionObserver:
    """FreeCAD's selection and pre-selection (Gui.Selection.addObserver): each change updates
    the overlay of the views with shadows of its document."""

    def __init__(self, states):
        self.states = states  # the views' shadow states (_documents._states)
        self.preselection = None  # (document, object, subname) while FreeCAD pre-selects

    def _changed(self, document):
        # At once, so that a script's next saveImage shows the change: FreeCAD calls its
        # observers after its own picking and selection actions, outside any traversal of the
        # overlay's nodes, and the overlay's changes stay below the group.
        for state in list(self.states.values()):
            if not document or state.document == document:
                state.highlight.update()

    def addSelection(self, document, obj, sub, point):  # noqa: N802  (FreeCAD's names)
        self._changed(document)

    def removeSelection(self, document, obj, sub):  # noqa: N802
        self._changed(document)

    def setSelection(self, document):  # noqa: N802
        self._changed(document)

    def clearSelection(self, document):  # noqa: N802
        self._changed(document)

    def setPreselection(self, document, obj, sub):  # noqa: N802
        self.preselection = (document, obj, sub)
        self._changed(document)

    def removePreselection(self, document, obj, sub):  # noqa: N802
        self.preselection = None
        self._changed(document)
