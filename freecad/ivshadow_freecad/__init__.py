"""Transparent, coloured shadows in FreeCAD's 3D view (docs/FREECAD.md).

    import ivshadow.freecad as shadows
    shadows.enable()                  # the active 3D view, with the preferences' settings
    shadows.enable(light_direction=(0.3, 0.5, -1), ground=False, renderer="RASTER")
    shadows.is_enabled()              # True
    shadows.disable()                 # FreeCAD's own picture again

enable() puts the view's model into a TransparentShadowGroup lit by one
DeepShadowDirectionalLight, with an automatic ground under it, and turns FreeCAD's headlight
(and backlight) off for the model, so that the shadows are as dark as the light makes them.

Where the group goes, and why. FreeCAD draws a document from its SoFCUnifiedSelection node
(`view.getSceneGraph()`): every view provider's root is a child of it, and both the live view
and `saveImage` (which builds a scene of its own around that node, with FreeCAD's headlight and
camera) draw it. A group put above it, in the render manager's scene, would shadow the live view
but not `saveImage`; so the group goes inside it and the view providers' roots move into the
group. FreeCAD appends the root of an object created later to the SoFCUnifiedSelection node: a
node sensor on it moves the newcomer into the group before the next redraw (the redraw sensor
has a lower priority). FreeCAD removes a deleted object's root from the SoFCUnifiedSelection
node only if it is a direct child (View3DInventorViewer::removeViewProvider looks it up with
findChild and does nothing when it is not there), so a Gui document observer removes it from
the group. FreeCAD's own nodes there (its event callback, the dimensions, the "on top"
selection group, the editing root of the sketcher and the transform dragger) stay where they
are, outside the group, lit by copies of the headlight so they look as before; picking follows
the roots' paths wherever they are, since FreeCAD finds the view provider of a picked path from
the nodes along it.
"""

# The package's modules, one job each: _settings (the settings' tables, FreeCAD's preferences,
# the settings a document keeps), _scene (helpers on Coin's nodes, the 3D view and its
# document), _shadows (_Shadows: what enable() adds to one view), _highlight (_Highlight:
# FreeCAD's highlight of faces drawn again for the tracer), _mesh (FreeCAD's triangles and
# material that it draws them with), _selection (_SelectionObserver) and _documents
# (_DocumentObserver, and the registries: the views with shadows, the observers).

import FreeCAD as App

import ivshadow  # noqa: F401  (loads the plugin and registers the nodes with Coin)

from ._documents import _states
from ._highlight import highlight_colours
from ._scene import _active_view, _address, _document_of
from ._settings import (DEFAULTS, META_KEY, PARAMETERS, PRESETS,
                        _resolve, _store, _store_disabled, save_preferences,
                        settings_from_preferences, stored_settings)
from ._shadows import _Shadows

__all__ = ["enable", "disable", "is_enabled", "group", "renderer_in_use", "refresh",
           "settings_from_preferences", "save_preferences", "stored_settings",
           "highlight_colours", "PRESETS", "PARAMETERS", "DEFAULTS", "META_KEY"]


def enable(view=None, *, light_direction=None, ground=None, light_location=None, **settings):
    """Shadows in `view` (a FreeCAD 3D view; the active one when None).

    light_direction: the direction the light travels in document coordinates, as Coin's
    DirectionalLight.direction (None: the preferences' preset); with a point light, the line
    from its place through the model's centre. light_location: a point light at this place in
    document coordinates (None: the preferences' light). ground: the automatic ground on or off
    (None: the preference). settings: any of DEFAULTS' keys (preset, light_type,
    light_distance, light_color, intensity, ground_size, ground_color, ground_transparency,
    renderer), or fields of the TransparentShadowGroup by name (movingResolution=0.5,
    transparency="COIN_BLENDING").
    Called on a view with shadows, changes their settings."""
    view = _active_view(view)
    document = _document_of(view)
    direction, resolved, location = _resolve(light_direction, ground, settings, light_location,
                                             stored_settings(App.getDocument(document)))
    key = _address(view.getSceneGraph())
    state = _states.get(key)
    if state is None:
        state = _Shadows(view)
        state.apply(direction, resolved, location)
        state.insert()
        _states[key] = state
    else:
        state.apply(direction, resolved, location)
    _store(document, direction, resolved, location)
    return state.group


def disable(view=None):
    """FreeCAD's own picture in `view` again: the model back where FreeCAD keeps it, its
    headlight as it was, and the document's settings saying shadows are off (saved now, it
    opens without them). Nothing happens in a view without shadows."""
    view = _active_view(view)
    state = _states.pop(_address(view.getSceneGraph()), None)
    if state is not None:
        state.remove()
        _store_disabled(state.document)


def is_enabled(view=None):
    """Whether `view` (the active 3D view when None) has shadows."""
    view = _active_view(view)
    return _address(view.getSceneGraph()) in _states


def refresh():
    """Every view with shadows takes the preferences' settings again (the preferences page
    calls this when it saves)."""
    for state in _states.values():
        direction, resolved, location = _resolve(None, None, {})
        state.apply(direction, resolved, location)
        _store(state.document, direction, resolved, location)


def group(view=None):
    """The TransparentShadowGroup of `view`, or None: its fields and statistics."""
    state = _states.get(_address(_active_view(view).getSceneGraph()))
    return state.group if state else None


def renderer_in_use(view=None):
    """How `view` (the active 3D view when None) drew its shadows in its last frame, the
    renderer setting's AUTO resolved: "TRACER" (traced on the CPU: a machine without a GPU) or
    "RASTER" (GL's shading on a GPU); None without shadows or before their first frame."""
    shadow_group = group(view)
    return ivshadow.renderer_in_use(shadow_group) if shadow_group is not None else None
