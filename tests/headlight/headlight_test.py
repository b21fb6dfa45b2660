#!/usr/bin/env python3
"""The headlight of an examiner viewer and the shadows (issue 38, "generic hosts"): the documented
way to keep shadows dark (docs/INTEGRATION.md, "Keep the shadows dark in a viewer": the
viewer's headlight off) tested by pixel in the two examples that follow it, the C++ SoQt
application (examples/soqt_add_shadows.cpp) and the same in pivy
(examples/python/soqt_add_shadows.py), each run as written and with --headlight, which keeps
the viewer's headlight on.

    headlight_test.py CPP_EXAMPLE PIVY_EXAMPLE SCENE WORK_DIR XSERVER_DIR

Runs under the suite's X server (fixture xserver; its window manager maps the windows at their
size) with /usr/bin/python3, which has Debian's pivy and PIL; PYTHONPATH names the build's
Python module. Exit 77 (skipped) when pivy's SoQt or PIL is missing.

The scene (headlight_scene.iv): a grey floor (diffuse 0.5, no ambient) seen straight from
above by an orthographic camera 6 units high, an opaque square 1 above it at x 0.5..1,
y -0.25..0.25. The examples put their DeepShadowLight 1.75 above the middle of the scene's
bounds, (0, 0, 2.25), after the scene's camera. From the geometry:
- the shadow: (1.4, 0, 0) towards the light, along (-1.4, 0, 2.25), reaches z = 1 at
  x = 1.4 (1 - 1 / 2.25) = 0.78: inside the square; the camera sees it (the square covers
  x <= 1 only). Its nearest shadow edge is 0.4 away (the shadow spans x 0.9..1.8);
- the lit point (-1.4, 0, 0): the mirror image, nothing between it and the light, which it
  sees at cos = 2.25 / |(1.4, 0, 2.25)| = 0.849: 0.5 x 0.849 x 255 = 108 levels;
- the viewer's headlight (SoQt's, direction (1, -1, -10) in the camera's coordinates) falls on
  the floor at cos = 10 / sqrt(102) = 0.990 and adds 0.5 x 0.990 x 255 = 126 levels to both.
So with the headlight off the shadow keeps only the ambient light (none: 0 levels) and the lit
floor 108; with it on the shadow is 126 (the headlight alone) and the lit floor 234: the shadow
is then over half as bright as the lit floor. The camera's view of 6 units high fills the GL
widget's height when it is wider than high (min(width, height) / 6 pixels a unit).
"""
import os
import subprocess
import sys

# The expected levels, and a tolerance of 4: 8-bit rounding, and Coin's per-vertex lighting of
# the point light over the floor's 0.25 grid (interpolating between vertices that see the light
# at cos 0.874 and 0.832 is within half a level of the exact 0.849 at the point).
TOLERANCE = 4
LIT = 0.5 * 255 * 2.25 / (1.4 ** 2 + 2.25 ** 2) ** 0.5
HEADLIGHT = 0.5 * 255 * 10 / 102 ** 0.5


def mean_level(image, point, size):
    """The mean grey level over the 5 x 5 pixels around the document point `point` (x, y)."""
    width, height = size
    scale = min(width, height) / 6.0
    column = int(round(width / 2 + point[0] * scale))
    row = int(round(height / 2 - point[1] * scale))
    values = [sum(image.getpixel((column + dx, row + dy))) / 3.0
              for dx in range(-2, 3) for dy in range(-2, 3)]
    return sum(values) / len(values)


def screenshot(command, path, display):
    """Runs an example with --screenshot; should the window not have been drawn by the time the
    example reads it back (all black: a loaded machine, the window manager mapping it late),
    runs it again with a longer wait. Returns the picture, or None and the output."""
    from PIL import Image
    # Screen 1, shared under a lock with the other tests that read windows back from the
    # screen (tests/xserver/xserver.sh), where no scripted viewer test's window comes on top.
    environment = dict(os.environ, DISPLAY=display + ".1")
    output = ""
    for wait in (3000, 6000, 12000):
        if os.path.exists(path):
            os.remove(path)
        run = subprocess.run(command + ["--quit-after-ms", str(wait), "--screenshot", path],
                             env=environment, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             universal_newlines=True, timeout=120)
        output = run.stdout
        if run.returncode != 0 or not os.path.exists(path):
            return None, "exit %d: %s" % (run.returncode, output)
        image = Image.open(path).convert("RGB")
        if image.getextrema()[0][1] > 0:
            return image, output
    return None, "the window stayed black: " + output


def main():
    cpp_example, pivy_example, scene, work, xserver = sys.argv[1:6]
    try:
        import PIL  # noqa: F401
        from pivy.gui import soqt  # noqa: F401
    except ImportError as error:
        print("SKIP: %s (Debian python3-pivy and python3-pil)" % error)
        return 77
    with open(os.path.join(xserver, "display")) as f:
        display = f.read().strip()
    os.makedirs(work, exist_ok=True)

    programs = {"cpp": [cpp_example, scene], "pivy": [sys.executable, pivy_example, scene]}
    failed = 0
    for name, command in programs.items():
        for headlight in (False, True):
            label = "%s, headlight %s" % (name, "on (--headlight)" if headlight else
                                          "off (the documented way)")
            path = os.path.join(work, "%s_headlight_%s.png" % (name, "on" if headlight else "off"))
            image, output = screenshot(command + (["--headlight"] if headlight else []), path,
                                       display)
            if image is None:
                print("FAIL: %s: no picture: %s" % (label, output[-2000:]))
                failed += 1
                continue
            size = image.size
            shadow = mean_level(image, (1.4, 0.0), size)
            lit = mean_level(image, (-1.4, 0.0), size)
            if headlight:
                checks = [("the shadow is the headlight's light alone",
                           abs(shadow - HEADLIGHT) <= TOLERANCE),
                          ("the lit floor is the light's and the headlight's",
                           abs(lit - min(255.0, LIT + HEADLIGHT)) <= TOLERANCE),
                          ("washed out: the shadow over half as bright as the lit floor",
                           shadow > 0.5 * lit)]
            else:
                checks = [("the shadow is dark (no ambient light)", shadow <= TOLERANCE),
                          ("the lit floor is the light's alone", abs(lit - LIT) <= TOLERANCE),
                          ("the shadow under a tenth of the lit floor", shadow < 0.1 * lit)]
            for what, passed in checks:
                failed += 0 if passed else 1
                print("%s: %s: %s (shadow %.1f, lit %.1f; expected shadow %.1f, lit %.1f, "
                      "picture %dx%d)" % ("ok" if passed else "FAIL", label, what, shadow, lit,
                                          HEADLIGHT if headlight else 0.0,
                                          min(255.0, LIT + HEADLIGHT) if headlight else LIT,
                                          size[0], size[1]))
    print("pictures in %s" % work)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
