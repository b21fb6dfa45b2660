#!/usr/bin/env python3
"""The FreeCAD add-on in FreeCAD itself (Debian's freecad 0.20), under the suite's X server.

    freecad_test.py BUILD_DIR PYTHON_DIR WORK_DIR XSERVER_DIR MACRO

Installs the build into WORK_DIR/prefix (cmake --install), gives FreeCAD a fresh home whose
user Mod directory holds the pointer that IVSHADOW_FREECAD_MOD_DIR installs (a Mod folder whose
Init.py puts the prefix's Python directory PYTHON_DIR on FreeCAD's sys.path), starts the GUI
with MACRO (shadows_macro.py or interaction_macro.py, which share macro_common.py) and reports
its checks. Nothing else tells FreeCAD where the
add-on or the plugin are: no PYTHONPATH, no LD_LIBRARY_PATH.
Exit 77 (skipped) when FreeCAD is not installed.
"""
import json
import os
import shutil
import subprocess
import sys


def main():
    build, python_dir, work, xserver, macro = sys.argv[1:6]
    freecad = shutil.which("freecad")
    if not freecad:
        print("SKIP: FreeCAD is not installed (Debian package freecad; ./run installs it)")
        return 77

    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    prefix = os.path.join(work, "prefix")
    subprocess.run(["cmake", "--install", build, "--prefix", prefix], check=True,
                   stdout=subprocess.DEVNULL)

    home = os.path.join(work, "home")
    pointer = os.path.join(home, ".local", "share", "FreeCAD", "Mod", "IvShadow")
    os.makedirs(pointer)
    with open(os.path.join(pointer, "Init.py"), "w") as f:
        f.write("import sys\nsys.path.append(%r)\n" % os.path.join(prefix, python_dir))

    with open(os.path.join(xserver, "display")) as f:
        display = f.read().strip()
    result = os.path.join(work, "result.json")
    environment = {key: value for key, value in os.environ.items()
                   if key not in ("LD_LIBRARY_PATH", "PYTHONPATH")}
    # Screen 1, which the tests that read windows back from the screen share under one lock
    # (tests/xserver/xserver.sh): on screen 0 the scripted viewer tests' windows, opened at
    # any time, came on top of FreeCAD's live view while it was read.
    environment.update(HOME=home, DISPLAY=display + ".1", QTWEBENGINE_DISABLE_SANDBOX="1",
                       IVSHADOW_FREECAD_RESULT=result, IVSHADOW_FREECAD_WORK=work,
                       IVSHADOW_FREECAD_PREFIX=prefix,
                       # FreeCAD imports the macro and macro_common.py as modules: no
                       # __pycache__ in the source tree.
                       PYTHONDONTWRITEBYTECODE="1")
    for variable in ("XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"):
        environment.pop(variable, None)
    log = os.path.join(work, "freecad.log")
    with open(log, "w") as output:
        try:
            # About 10 s here; FreeCAD's start is most of it.
            subprocess.run([freecad, macro], env=environment, stdout=output,
                           stderr=subprocess.STDOUT, timeout=240)
        except subprocess.TimeoutExpired:
            print("FAIL: FreeCAD did not finish the macro in 240 s (log: %s)" % log)
    checks = []
    if os.path.exists(result):
        with open(result) as f:
            checks = json.load(f)
    if not checks or checks[-1]["name"] != "macro finished":
        print("FAIL: the macro did not finish; FreeCAD's output ends:")
        with open(log) as f:
            print(f.read()[-3000:])
    failed = 0
    for entry in checks:
        verdict = "ok" if entry["passed"] else "FAIL"
        failed += 0 if entry["passed"] else 1
        print("%s: %s %s" % (verdict, entry["name"], json.dumps(entry["measured"])))
    print("pictures in %s" % work)
    finished = bool(checks) and checks[-1]["name"] == "macro finished"
    return 1 if failed or not finished else 0


if __name__ == "__main__":
    sys.exit(main())
