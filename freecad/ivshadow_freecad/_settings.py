"""The add-on's settings: their tables (PARAMETERS, PRESETS, DEFAULTS, META_KEY), FreeCAD's
preferences (settings_from_preferences, save_preferences), the settings saved with a document
(stored_settings, _store, _store_disabled), and how an enable() call's arguments, the
document's settings and the preferences resolve into the settings a view gets (_resolve)."""

import json
import math

import FreeCAD as App

# Where the add-on's preferences live in FreeCAD's parameters (Tools > Edit parameters).
PARAMETERS = "User parameter:BaseApp/Preferences/Mod/IvShadow"

# The direction the light travels, in document coordinates (z up; FreeCAD's default isometric
# camera looks along (-1, 1, -1)). Over the shoulder: from behind and to the left of that camera
# and high, so the lit faces face the viewer and shadows fall back and to the right. Top: straight
# down, shadows right under the parts. Front-left: from the front-left and high.
PRESETS = {
    "OverTheShoulder": (-0.35, 0.55, -1.0),
    "Top": (0.0, 0.0, -1.0),
    "FrontLeft": (0.6, 0.8, -1.0),
}

# The settings and their defaults (also the preferences' defaults). Colours are (r, g, b) in 0..1.
DEFAULTS = {
    "preset": "OverTheShoulder",
    # "Directional": a light from far away (the sun), travelling along the preset's direction;
    # "Point": a lamp at a place, by default on the preset's line through the model's centre,
    # `light_distance` times the model's size away from it (enable(light_location=...) names
    # the place in document coordinates instead).
    "light_type": "Directional",
    "light_distance": 2.0,
    "light_color": (1.0, 1.0, 1.0),
    "intensity": 1.0,
    "ground": True,
    # The ground's side, as a multiple of the model's largest horizontal extent.
    "ground_size": 3.0,
    "ground_color": (0.8, 0.8, 0.8),
    # 0 (opaque) .. 100 (invisible), as FreeCAD's own Transparency property.
    "ground_transparency": 0,
    # SoTransparentShadowGroup.renderer: AUTO traces on the CPU where GL is a software
    # rasteriser (Mesa's llvmpipe) and rasterises on a GPU.
    "renderer": "AUTO",
    # FreeCAD's transparent parts: "Exact" composites them in depth order per pixel (the
    # group's transparency PEELED); "FreeCAD" leaves them to Coin's blending, as FreeCAD draws
    # them without shadows (COIN_BLENDING).
    "transparency": "Exact",
    # A dragger on the light in the view: turning it turns the light.
    "dragger": False,
}

_TRANSPARENCY = {"Exact": "PEELED", "FreeCAD": "COIN_BLENDING"}
_LIGHT_TYPES = {"Directional": "DeepShadowDirectionalLight", "Point": "DeepShadowLight"}


def _colour_from_parameter(value):
    # FreeCAD stores colours as 0xRRGGBBAA in an unsigned parameter.
    return (((value >> 24) & 0xFF) / 255.0, ((value >> 16) & 0xFF) / 255.0,
            ((value >> 8) & 0xFF) / 255.0)


def _colour_to_parameter(colour):
    r, g, b = (max(0, min(255, int(round(c * 255)))) for c in colour)
    return (r << 24) | (g << 16) | (b << 8)


def settings_from_preferences():
    """The settings stored in FreeCAD's parameters (PARAMETERS), DEFAULTS where none is set."""
    group = App.ParamGet(PARAMETERS)
    settings = dict(DEFAULTS)
    settings["preset"] = group.GetString("LightPreset", DEFAULTS["preset"])
    if settings["preset"] not in PRESETS:
        settings["preset"] = DEFAULTS["preset"]
    settings["light_type"] = group.GetString("LightType", DEFAULTS["light_type"])
    if settings["light_type"] not in _LIGHT_TYPES:
        settings["light_type"] = DEFAULTS["light_type"]
    settings["light_distance"] = group.GetFloat("LightDistance", DEFAULTS["light_distance"])
    settings["light_color"] = _colour_from_parameter(
        group.GetUnsigned("LightColor", _colour_to_parameter(DEFAULTS["light_color"])))
    settings["intensity"] = group.GetFloat("LightIntensity", DEFAULTS["intensity"])
    settings["ground"] = group.GetBool("Ground", DEFAULTS["ground"])
    settings["ground_size"] = group.GetFloat("GroundSize", DEFAULTS["ground_size"])
    settings["ground_color"] = _colour_from_parameter(
        group.GetUnsigned("GroundColor", _colour_to_parameter(DEFAULTS["ground_color"])))
    settings["ground_transparency"] = group.GetInt("GroundTransparency",
                                                   DEFAULTS["ground_transparency"])
    settings["renderer"] = group.GetString("Renderer", DEFAULTS["renderer"])
    settings["transparency"] = group.GetString("Transparency", DEFAULTS["transparency"])
    if settings["transparency"] not in _TRANSPARENCY:
        settings["transparency"] = DEFAULTS["transparency"]
    settings["dragger"] = group.GetBool("LightDragger", DEFAULTS["dragger"])
    return settings


def save_preferences(settings):
    """Stores `settings` (keys of DEFAULTS) in FreeCAD's parameters."""
    group = App.ParamGet(PARAMETERS)
    group.SetString("LightPreset", settings["preset"])
    group.SetString("LightType", settings["light_type"])
    group.SetFloat("LightDistance", float(settings["light_distance"]))
    group.SetUnsigned("LightColor", _colour_to_parameter(settings["light_color"]))
    group.SetFloat("LightIntensity", float(settings["intensity"]))
    group.SetBool("Ground", bool(settings["ground"]))
    group.SetFloat("GroundSize", float(settings["ground_size"]))
    group.SetUnsigned("GroundColor", _colour_to_parameter(settings["ground_color"]))
    group.SetInt("GroundTransparency", int(settings["ground_transparency"]))
    group.SetString("Renderer", settings["renderer"])
    group.SetString("Transparency", settings["transparency"])
    group.SetBool("LightDragger", bool(settings["dragger"]))


def _unit(vector):
    x, y, z = (float(c) for c in vector)
    length = math.sqrt(x * x + y * y + z * z)
    if length == 0:
        raise ValueError("light_direction: a direction of zero length")
    return (x / length, y / length, z / length)


# The key of a document's Meta map that holds its shadows' settings (JSON), saved with it.
META_KEY = "IvShadow"


def stored_settings(document):
    """The shadow settings saved with an App document (its Meta map, key META_KEY), or {}."""
    try:
        return json.loads(document.Meta.get(META_KEY, "{}"))
    except (ValueError, AttributeError):
        return {}


def _store(document_name, direction, settings, location):
    document = App.getDocument(document_name)
    stored = {key: (list(value) if isinstance(value, tuple) else value)
              for key, value in settings.items() if key in DEFAULTS}
    stored["light_direction"] = list(direction)
    stored["light_location"] = list(location) if location is not None else None
    # Shadows are on: a document saved now and opened again gets them back (init_gui.py).
    stored["enabled"] = True
    _write_meta(document, stored)


def _write_meta(document, stored):
    text = json.dumps(stored, sort_keys=True)
    meta = document.Meta
    if meta.get(META_KEY) != text:
        meta[META_KEY] = text
        document.Meta = meta


def _store_disabled(document_name):
    try:
        document = App.getDocument(document_name)
    except NameError:  # closed meanwhile
        return
    stored = stored_settings(document)
    if stored.get("enabled"):
        stored["enabled"] = False
        _write_meta(document, stored)


def _resolve(light_direction, ground, settings, light_location=None, stored=None):
    resolved = settings_from_preferences()
    from_stored = False
    if stored:
        # The document's own settings over the preferences (docs/FREECAD.md, "Per document").
        for key in DEFAULTS:
            if key in stored:
                value = stored[key]
                resolved[key] = tuple(value) if isinstance(value, list) else value
        if light_direction is None and light_location is None:
            if stored.get("light_location") is not None and resolved["light_type"] == "Point":
                light_location = stored["light_location"]
            elif stored.get("light_direction") is not None:
                light_direction = stored["light_direction"]
            from_stored = True
    fields = {}
    for key, value in settings.items():
        if key in DEFAULTS:
            resolved[key] = value
        elif key[:1].islower() and key.replace("_", "").isalnum():
            # Any other keyword names a field of the TransparentShadowGroup (movingResolution,
            # transparency, ...), set as in a file.
            fields[key] = value
        else:
            raise TypeError("enable(): unknown setting %r" % key)
    if ground is not None:
        resolved["ground"] = bool(ground)
    if resolved["preset"] not in PRESETS:
        raise ValueError("preset: one of %s" % ", ".join(PRESETS))
    if light_direction is not None and light_location is None and \
            "light_type" not in settings and not from_stored:
        resolved["light_type"] = "Directional"  # a direction named: a light from far away
    if light_location is not None:
        resolved["light_type"] = "Point"
        light_location = tuple(float(c) for c in light_location)
        if len(light_location) != 3 or not all(math.isfinite(c) for c in light_location):
            raise ValueError("light_location: three finite coordinates")
    if resolved["light_type"] not in _LIGHT_TYPES:
        raise ValueError("light_type: Directional or Point, not %r" % resolved["light_type"])
    direction = _unit(light_direction if light_direction is not None
                      else PRESETS[resolved["preset"]])
    resolved["fields"] = fields
    return direction, resolved, light_location
