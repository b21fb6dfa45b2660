#!/usr/bin/env python3
"""The Python module with Debian's pivy (python3-pivy).

    pivy_test.py IVSHADOW EXAMPLE.py PANE.iv SCENES_DIR WORK_DIR

Run with the Python that has pivy and PYTHONPATH at the build tree's python/ directory.
Checks that without the module pivy cannot read a file naming the nodes (the failure the
module exists for), that with it the nodes are created by name, read from files and have
fields to set, that examples/python/variants.py renders each of its variants with the same
pixels as `ivshadow render` of the hand-written PANE.iv with the same assignments, and that
render() and reference() return statistics and raise IvShadowError naming the file or field.
Exit 77 (skipped) when pivy is not installed.
"""
import os
import struct
import subprocess
import sys
import json

try:
    from pivy import coin  # noqa: F401  (only whether it is there; the module loads it)
except ImportError:
    print("SKIP: pivy is not installed for %s (Debian package python3-pivy)" % sys.executable)
    sys.exit(77)


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def png_size(path):
    with open(path, "rb") as f:
        header = f.read(24)
    if header[:8] != b"\x89PNG\r\n\x1a\n":
        fail("%s is not a PNG" % path)
    return struct.unpack(">II", header[16:24])


def largest_difference(ivshadow_exe, a, b, work):
    metrics = os.path.join(work, "metrics.json")
    subprocess.run([ivshadow_exe, "compare", a, b, "--json", metrics], check=True,
                   capture_output=True)
    with open(metrics) as f:
        return json.load(f)["all"]["max_abs_error"]


def main():
    ivshadow_exe, example, pane, scenes, work = sys.argv[1:6]
    os.makedirs(work, exist_ok=True)
    coloured = os.path.join(scenes, "coloured_shadows.iv")

    # Without the module: pivy's Coin cannot load the plugin for a node it does not know.
    bare = subprocess.run(
        [sys.executable, "-c",
         "from pivy import coin\n"
         "i = coin.SoInput()\n"
         "i.openFile(%r)\n"
         "root = coin.SoDB.readAll(i)\n"
         "lamp = coin.SoNode.getByName(coin.SbName('Lamp'))\n"
         "print('read' if root and lamp and lamp.getTypeId().getName().getString() == "
         "'DeepShadowLight' else 'unread')\n" % coloured],
        capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=""))
    if "unread" not in bare.stdout:
        fail("pivy read the nodes without the module: %r %r" % (bare.stdout, bare.stderr[-300:]))

    # The module works imported after pivy too (it promotes the loaded libCoin to global).
    after = subprocess.run(
        [sys.executable, "-c",
         "from pivy import coin\n"
         "import ivshadow\n"
         "i = coin.SoInput()\n"
         "i.openFile(%r)\n"
         "coin.SoDB.readAll(i)\n"
         "print(coin.SoNode.getByName(coin.SbName('Lamp')).getTypeId().getName().getString())\n"
         % coloured], capture_output=True, text=True)
    if after.stdout.strip() != "DeepShadowLight":
        fail("ivshadow imported after pivy: %r %r" % (after.stdout, after.stderr[-300:]))

    import ivshadow
    from pivy import coin

    group = coin.SoType.fromName(coin.SbName("TransparentShadowGroup")).createInstance()
    if group is None or group.getTypeId().getName().getString() != "TransparentShadowGroup":
        fail("SoType.fromName('TransparentShadowGroup').createInstance() gave %r" % group)
    # The plugin's C entry point through pivy's node: a group that never drew reads None.
    if ivshadow.renderer_in_use(group) is not None:
        fail("renderer_in_use() of a group never rendered: %r" % ivshadow.renderer_in_use(group))
    light = coin.SoType.fromName(coin.SbName("DeepShadowLight")).createInstance()
    light.getField("maxLayers").set("2")
    if light.getField("maxLayers").get() != "2":
        fail("DeepShadowLight.maxLayers reads back as %r" % light.getField("maxLayers").get())

    reader = coin.SoInput()
    if not reader.openFile(coloured):
        fail("cannot open %s" % coloured)
    root = coin.SoDB.readAll(reader)
    lamp = coin.SoNode.getByName(coin.SbName("Lamp"))
    if root is None or lamp is None or lamp.getTypeId().getName().getString() != "DeepShadowLight":
        fail("reading %s through pivy did not give its DeepShadowLight" % coloured)

    # The example, against the CLI's render of the same scene written by hand.
    out = os.path.join(work, "example")
    ran = subprocess.run([sys.executable, example, out, "--size", "160x120"],
                         capture_output=True, text=True)
    if ran.returncode != 0:
        fail("the example exited %d: %s" % (ran.returncode, ran.stderr))
    if "refused as expected (exit 2)" not in ran.stdout or "no field 'colour'" not in ran.stdout:
        fail("the example did not show the refused assignment: %s" % ran.stdout)
    sys.path.insert(0, os.path.dirname(example))
    from variants import VARIANTS
    for name, colour, transparency in VARIANTS:
        mine = os.path.join(out, name + ".png")
        cli = os.path.join(work, "cli-" + name + ".png")
        subprocess.run([ivshadow_exe, "render", pane, "-o", cli, "--size", "160x120",
                        "--frames", "1", "--set", "PaneMaterial.diffuseColor=" + colour,
                        "--set", "PaneMaterial.transparency=%g" % transparency], check=True,
                       capture_output=True)
        difference = largest_difference(ivshadow_exe, cli, mine, work)
        if difference != 0:
            fail("%s: the pivy render differs from the CLI's by up to %d steps" %
                 (name, difference))
    print("example: %d variants pixel-identical to the CLI's renders" % len(VARIANTS))

    # render() returns the --stats; of a path, and with assignments.
    stats = ivshadow.render(coloured, os.path.join(work, "path.png"), size=(96, 72),
                            sets=["Lamp.intensity=0.8"])
    if "frame_ms_median" not in stats or png_size(os.path.join(work, "path.png")) != (96, 72):
        fail("render() of a path: %r" % stats)
    # reference() of a pivy scene graph.
    result = ivshadow.reference(root, os.path.join(work, "reference.png"), size=(64, 48),
                                threads=2)
    if png_size(result["output"]) != (64, 48):
        fail("reference() wrote %r" % (png_size(result["output"]),))

    # Errors: Python exceptions naming the file, line or field.
    missing = os.path.join(work, "missing.iv")
    try:
        ivshadow.render(missing, os.path.join(work, "x.png"))
        fail("rendering a missing file raised nothing")
    except ivshadow.IvShadowError as error:
        if error.status != 2 or missing not in error.message:
            fail("a missing file: exit %d, %r" % (error.status, error.message))
    broken = os.path.join(work, "broken.iv")
    with open(broken, "w") as f:
        f.write("#Inventor V2.1 ascii\nTransparentShadowGroup {\n  DeepShadowLight {\n"
                "    maxLayers many\n  }\n}\n")
    try:
        ivshadow.render(broken, os.path.join(work, "x.png"))
        fail("rendering a broken file raised nothing")
    except ivshadow.IvShadowError as error:
        if error.status != 2 or broken + ":4: error:" not in error.message:
            fail("a broken file: exit %d, %r" % (error.status, error.message))
        print("a broken file: %s" % error.message.splitlines()[0])
    try:
        ivshadow.render(group, os.path.join(work, "x.png"), sets=["Lamp.intensity=1"])
        fail("an assignment to a node the graph lacks raised nothing")
    except ivshadow.IvShadowError as error:
        if error.status != 2 or "Lamp" not in error.message:
            fail("an unknown node: exit %d, %r" % (error.status, error.message))
        print("an unknown node: %s" % error.message.splitlines()[0])
    if os.path.exists(os.path.join(work, "x.png")):
        fail("a refused render left x.png")
    print("errors: raised as IvShadowError with the command's message")


if __name__ == "__main__":
    main()
