"""Checks that an unpacked GPU kit (bench/gpu_kit.sh) depends on nothing of this machine but
glibc, the C++ runtime and the GL driver:
  - statically: every library that `ldd` resolves for the kit's binaries and libraries,
  - that the headless programs (ivshadow, gl_tests, the benchmarks) load no Qt, SoQt or ICU,
  - at run time: every library a render through the kit loads (LD_DEBUG), the ones opened by
    name (libEGL by libepoxy, libGL by Coin, TBB's allocator by Embree) included.
The driver is whatever libglvnd's libEGL/libGLX open through the vendor files (egl_vendor.d),
and what those need in turn: here Mesa's libEGL_mesa, its DRI driver (swrast_dri.so),
libglapi, libgbm, libdrm, LLVM, wayland and xcb pieces; on the GPU machine NVIDIA's
libEGL_nvidia and its own libraries. Those belong to the machine's driver and must match its
kernel module, so the kit cannot carry them; anything else loaded from outside the kit means
the kit would need a package on the GPU machine, which cannot install any.
    python3 check_kit_libraries.py KIT_ROOT BUILD_REL SCENE OUT_PNG
"""
import os
import re
import subprocess
import sys

root, build_rel, scene, picture = sys.argv[1:5]
root = os.path.realpath(root)
bin_dir = os.path.join(root, build_rel, "bin")
lib_dir = os.path.join(root, build_rel, "lib")
# glibc's libraries and the compiler's runtime, which every machine that runs the kit has.
SYSTEM = re.compile(r"^(linux-vdso|ld-linux-x86-64|libc|libm|libmvec|libdl|libpthread|librt|"
                    r"libresolv|libutil|libanl|libnsl|libstdc\+\+|libgcc_s)\.so")
# libglvnd's dispatch libraries, in the kit, which open the vendor's (the driver's) library.
GLVND = {"libEGL.so.1", "libGLX.so.0", "libGL.so.1", "libOpenGL.so.0", "libGLdispatch.so.0"}
environment = {"PATH": "/usr/bin:/bin"}
problems = []


def inside(path):
    return os.path.realpath(path).startswith(root + os.sep)


# The headless programs load no GUI toolkit: Qt, SoQt and ICU (about 40 MB) are the viewer's
# alone (`ivshadow view` runs ivshadow-viewer).
HEADLESS = {"ivshadow", "gl_tests", "ivshadow_bench", "render_scene_graph"}
GUI = re.compile(r"^lib(Qt5|SoQt|icu)")

files = [os.path.join(d, f) for d in (bin_dir, lib_dir) for f in sorted(os.listdir(d))]
files = [f for f in files if not os.path.islink(f)]
for path in files:
    ldd = subprocess.run(["ldd", path], capture_output=True, text=True, env=environment)
    for line in ldd.stdout.splitlines():
        fields = line.split()
        if len(fields) < 3 or fields[1] != "=>":
            continue
        name, resolved = fields[0], fields[2]
        if os.path.basename(path) in HEADLESS and GUI.match(name):
            problems.append(f"{os.path.basename(path)}: loads {name}, a GUI library")
        if resolved == "not":
            problems.append(f"{os.path.basename(path)}: {name} not found")
        elif not inside(resolved) and not SYSTEM.match(name):
            problems.append(f"{os.path.basename(path)}: {name} resolves outside the kit, to {resolved}")

run = subprocess.run([os.path.join(bin_dir, "ivshadow"), "render", scene, "-o", picture,
                      "--size", "64x48"],
                     capture_output=True, text=True, env=dict(environment, LD_DEBUG="files,libs"))
if run.returncode != 0:
    problems.append(f"the render failed: {run.stderr.strip().splitlines()[-1:]}")
loader_of, tried, loaded = {}, {}, []
for line in run.stderr.splitlines():
    line = re.sub(r"^\s*\d+:\s*", "", line)
    match = re.match(r"file=(\S+) \[\d+\];\s+(?:needed by|dynamically loaded by) (\S+)", line)
    if match:
        loader_of[match.group(1)] = match.group(2)
        continue
    match = re.match(r"trying file=(\S+)", line)
    if match:
        tried[os.path.basename(match.group(1))] = match.group(1)
        continue
    match = re.match(r"file=(\S+) \[\d+\];\s+generating link map", line)
    if match:
        name = match.group(1)
        path = name if "/" in name else tried.get(name, name)
        loaded.append((name, path, loader_of.get(name, "")))
if not any(name == "libEGL.so.1" for name, _, _ in loaded):
    problems.append("the render never loaded libEGL.so.1")
for name, path, loader in loaded:
    if inside(path) or SYSTEM.match(os.path.basename(name)):
        continue
    # The driver: opened by the kit's libglvnd, or needed by a library from outside the kit
    # that got here that way.
    if (inside(loader) and os.path.basename(loader) in GLVND) or (loader and not inside(loader)):
        continue
    problems.append(f"{name} was loaded from {path} by {loader}")
driver = sorted({os.path.basename(path) for name, path, loader in loaded
                 if not inside(path) and not SYSTEM.match(os.path.basename(name))})
print(f"{len(files)} kit files checked with ldd; {len(loaded)} libraries loaded by a render, "
      f"from outside the kit besides glibc and the C++ runtime only the driver: {' '.join(driver)}")
for problem in problems:
    print("PROBLEM:", problem)
sys.exit(1 if problems else 0)
