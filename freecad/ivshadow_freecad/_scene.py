"""The scene-graph helpers the add-on's modules share: the names of its nodes, a node of one
of the plugin's types, a node's identity (its C++ address), the children of a group and the
roots of a document's view providers, and the 3D view (and its document) a call is about.
The nodes of the plugin's types are known to Coin once the package `ivshadow` has loaded the
plugin, which Python does before it imports this subpackage."""

import FreeCAD as App
from pivy import coin

_NAMES = {"dragger": "IvShadowLightDragger", "lamp_dragger": "IvShadowLampDragger",
          "group": "IvShadowGroup", "light": "IvShadowLight", "ground": "IvShadowGround",
          "model": "IvShadowModel", "host_lights": "IvShadowHostLights",
          "highlight": "IvShadowHighlight"}


def _type(name):
    node = coin.SoType.fromName(coin.SbName(name)).createInstance()
    if node is None:
        raise RuntimeError("the ivshadow plugin did not register %s with Coin" % name)
    return node


def _address(node):
    # pivy makes a new wrapper for every node it returns; the C++ address names the node.
    return int(node.this)


def _active_view(view):
    if view is not None:
        return view
    import FreeCADGui as Gui
    document = Gui.ActiveDocument
    view = document.ActiveView if document else None
    if view is None or not hasattr(view, "getSceneGraph"):
        raise RuntimeError("ivshadow.freecad: no active 3D view")
    return view


def _document_of(view):
    """The name of the document `view` shows: the one among its 3D views with its scene."""
    import FreeCADGui as Gui
    address = _address(view.getSceneGraph())
    for name in App.listDocuments():
        for candidate in Gui.getDocument(name).mdiViewsOfType("Gui::View3DInventor"):
            if _address(candidate.getSceneGraph()) == address:
                return name
    raise RuntimeError("ivshadow.freecad: the view shows no open document")


def _children(group):
    return [_address(group.getChild(i)) for i in range(group.getNumChildren())]


def _view_provider_roots(document_name):
    """The addresses of the root nodes of the view providers of a Gui document."""
    import FreeCADGui as Gui
    roots = set()
    if not document_name:
        return roots
    gui_document = Gui.getDocument(document_name)
    for obj in gui_document.Document.Objects:
        view_object = gui_document.getObject(obj.Name)
        root = getattr(view_object, "RootNode", None) if view_object else None
        if root is not None:
            roots.add(_address(root))
    return roots
