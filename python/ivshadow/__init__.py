"""ivshadow's nodes in pivy, and headless rendering of pivy scene graphs.

    import ivshadow            # before or after `from pivy import coin`
    from pivy import coin

Importing the module makes TransparentShadowGroup, DeepShadowLight, DeepShadowSpotLight,
DeepShadowDirectionalLight and PeelingSeparator known to Coin in this process: files that name
them read, and SoType.fromName(...).createInstance() creates them.

Why the module is needed: pivy loads libCoin with local symbols, so when Coin itself tries to
load the plugin for an unknown node name it cannot find its own SoBase::initClass ("unable to
figure out the C++ name mangling scheme"). The module loads libCoin with global symbols, then
loads the plugin library and calls ivshadow::init(), which registers every node directly, so
Coin's loader is never needed.

render() and reference() run the `ivshadow` executable (the same renderer as `ivshadow render`
and `ivshadow reference`) in a child process: a crash of a GL driver or a refused scene comes
back as an IvShadowError with the command's message, never as a crash of the interpreter.
render() keeps that process (`ivshadow variants-worker`, ivshadow/_worker.py) for the renders
that follow, so that a loop of renders pays for the process and its GL context once;
IVSHADOW_VARIANTS_WORKERS=0 runs `ivshadow render` for each instead.
"""

import atexit
import ctypes
import ctypes.util
import json
import os
import subprocess
import tempfile
import time

from . import _paths
from . import _worker

__all__ = ["IvShadowError", "render", "reference", "executable", "library", "renderer_in_use"]


class IvShadowError(Exception):
    """A render or reference the command refused or failed: `message` is the command's error
    (naming the file, line or field), `status` its exit status (2 bad input, 3 no GL context,
    1 anything else)."""

    def __init__(self, message, status):
        super().__init__(message)
        self.message = message
        self.status = status


def executable():
    """The `ivshadow` command the module runs: $IVSHADOW_EXE, else the one built or installed
    with the module."""
    return os.environ.get("IVSHADOW_EXE", _paths.EXECUTABLE)


def library():
    """The plugin library loaded into this process: $IVSHADOW_LIBRARY, else the one built or
    installed with the module."""
    return os.environ.get("IVSHADOW_LIBRARY", _paths.LIBRARY)


def _load_nodes():
    coin_library = ctypes.util.find_library("Coin") or "libCoin.so"
    # Global symbols for Coin first, and for the plugin that links it; a libCoin that pivy
    # already loaded with local symbols is promoted to global by the same call.
    ctypes.CDLL(coin_library, mode=ctypes.RTLD_GLOBAL)
    from pivy import coin  # noqa: F401  (SoDB.init, which the registration needs)

    plugin = ctypes.CDLL(library(), mode=ctypes.RTLD_GLOBAL)
    # ivshadow::init(), exported by the plugin (include/ivshadow/IvShadowInit.h).
    plugin["_ZN8ivshadow4initEv"]()
    # include/ivshadow/DeepShadowStatistics.h: the renderer the groups under a node drew with.
    plugin.ivshadow_renderer_in_use.argtypes = [ctypes.c_void_p]
    plugin.ivshadow_renderer_in_use.restype = ctypes.c_char_p
    return coin, plugin


_coin, _plugin = _load_nodes()


def renderer_in_use(node):
    """How the TransparentShadowGroups under the pivy `node` (or the group itself) drew their
    children in the last frame rendered in this process, `renderer AUTO` resolved: "TRACER"
    (traced on the CPU), "RASTER" (GL's shading), "MIXED" (groups differ), or None when no
    group has drawn yet."""
    # pivy's wrapper holds the node's C++ address.
    name = _plugin.ivshadow_renderer_in_use(int(node.this)).decode()
    return name or None


def _size_text(size):
    width, height = size
    return "%dx%d" % (int(width), int(height))


class _SceneFile:
    """A path for the command: the path given, or a pivy node written to a temporary .iv file
    with SoWriteAction (removed afterwards)."""

    def __init__(self, scene):
        self.temporary = None
        if isinstance(scene, (str, bytes, os.PathLike)):
            self.path = os.fsdecode(scene)
            return
        if not isinstance(scene, _coin.SoNode):
            raise TypeError("scene: expected a path or a pivy SoNode, not %s" %
                            type(scene).__name__)
        handle, self.temporary = tempfile.mkstemp(prefix="ivshadow-", suffix=".iv")
        os.close(handle)
        output = _coin.SoOutput()
        if not output.openFile(self.temporary):
            raise IvShadowError("%s: error: cannot write the scene graph" % self.temporary, 1)
        _coin.SoWriteAction(output).apply(scene)
        output.closeFile()
        self.path = self.temporary

    def message(self, text):
        # The temporary file is gone once the call returns; name what the caller passed.
        if self.temporary:
            text = text.replace(self.temporary, "<pivy scene graph>")
        return text

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if self.temporary:
            os.remove(self.temporary)


def _run(command, scene):
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        message = result.stderr.strip() or ("%s exited %d" % (command[1], result.returncode))
        raise IvShadowError(scene.message(message), result.returncode)
    return result


def _set_list(sets):
    return [sets] if isinstance(sets, str) else list(sets)


def _assignments(sets):
    words = []
    for assignment in _set_list(sets):
        words += ["--set", assignment]
    return words


_render_worker = _worker.RenderWorker()
atexit.register(_render_worker.close)


def render(scene, output, size=(800, 600), frames=1, sets=(), transparency=None):
    """Renders `scene` (a path or a pivy node) headlessly to `output` (.png, .jpg) as
    `ivshadow render` does, with the NAME.field=VALUE assignments of `sets`, and returns the
    statistics of `ivshadow render --stats` as a dict."""
    with _SceneFile(scene) as file, tempfile.TemporaryDirectory(prefix="ivshadow-") as scratch:
        stats = os.path.join(scratch, "stats.json")
        status = None
        if os.environ.get("IVSHADOW_VARIANTS_WORKERS") != "0":
            log = os.path.join(scratch, "render.log")
            status = _render_worker.try_render(executable(), {
                "scene": file.path, "output": os.fspath(output), "size": _size_text(size),
                "frames": int(frames), "stats": stats, "sets": _set_list(sets),
                "transparency": transparency or "", "log": log})
            if status is not None and status != 0:
                # The render's stderr, as _run reports a render process's.
                text = ""
                if os.path.exists(log):
                    with open(log, errors="replace") as f:
                        text = f.read().strip()
                raise IvShadowError(file.message(text or "render exited %d" % status), status)
        if status is None:
            command = [executable(), "render", file.path, "-o", os.fspath(output), "--size",
                       _size_text(size), "--frames", str(int(frames)), "--stats", stats]
            command += _assignments(sets)
            if transparency:
                command += ["--transparency", transparency]
            _run(command, file)
        with open(stats) as f:
            return json.load(f)


def reference(scene, output, size=(800, 600), sets=(), threads=0, pfm=None):
    """Renders the exact picture of `scene` (a path or a pivy node) on the CPU to `output`, as
    `ivshadow reference` does, and returns {"output", "size", "seconds"}."""
    with _SceneFile(scene) as file:
        command = [executable(), "reference", file.path, "-o", os.fspath(output), "--size",
                   _size_text(size), "--threads", str(int(threads))]
        command += _assignments(sets)
        if pfm:
            command += ["--pfm", os.fspath(pfm)]
        started = time.monotonic()
        _run(command, file)
        return {"output": os.fspath(output), "size": _size_text(size),
                "seconds": time.monotonic() - started}
