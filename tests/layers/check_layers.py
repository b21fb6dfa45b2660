#!/usr/bin/env python3
"""Fails when a file of the project includes a file of a layer it may not depend on.

Usage: check_layers.py ROOT TABLE [--install-list FILE]

ROOT is the source tree, TABLE the layer table (tests/layers/layers.txt describes the format).
Every #include of a .h or .cpp file under ROOT that names a file of the project (looked up
beside the including file, from ROOT, and from ROOT/include) must stay within what the
including file's layer may use. With --install-list, the headers under include/ivshadow/ must
be exactly those the CMake file lists (the public API is the installed set, nothing else).
Prints one line per violation and exits 1 if there is any.
"""

import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')
SOURCE_SUFFIXES = (".h", ".cpp")
SKIPPED_FOLDERS = {".git", "build"}


def read_table(path):
    """Returns (layers in table order, {path prefix: layer}, {layer: set of direct deps})."""
    entries = []  # (line number, text); an indented line continues the entry above it
    with open(path, encoding="utf-8") as table:
        for number, raw in enumerate(table, 1):
            text = raw.split("#", 1)[0].rstrip()
            if not text.strip():
                continue
            if raw[0].isspace() and entries:
                entries[-1] = (entries[-1][0], entries[-1][1] + " " + text.strip())
            else:
                entries.append((number, text.strip()))
    order, prefixes, deps = [], {}, {}
    for number, line in entries:
        if ":" not in line:
            raise ValueError(f"{path}:{number}: expected 'layer paths... : deps...'")
        left, right = line.split(":", 1)
        words = left.split()
        if len(words) < 2:
            raise ValueError(f"{path}:{number}: a layer needs a name and a path")
        layer, paths = words[0], words[1:]
        order.append(layer)
        for prefix in paths:
            prefixes[prefix] = layer
        deps[layer] = set(right.split())
    for layer, names in deps.items():
        unknown = names - set(order)
        if unknown:
            raise ValueError(f"{path}: layer {layer} names unknown layers {sorted(unknown)}")
    return order, prefixes, deps


def allowed_layers(deps):
    """Each layer with everything it may include: itself and its deps, transitively."""
    closure = {}
    for layer in deps:
        seen, todo = {layer}, [layer]
        while todo:
            for dep in deps[todo.pop()]:
                if dep not in seen:
                    seen.add(dep)
                    todo.append(dep)
        closure[layer] = seen
    return closure


def layer_of(relative, prefixes):
    """The layer of the longest table path that `relative` (a path from ROOT) falls under."""
    stem = os.path.splitext(relative)[0]
    best = None
    for prefix, layer in prefixes.items():
        matches = relative.startswith(prefix) if prefix.endswith("/") else stem == prefix
        if matches and (best is None or len(prefix) > len(best[0])):
            best = (prefix, layer)
    return best[1] if best else None


def resolve(root, including, name):
    """The project file an #include names, as a path from ROOT, or None (system, generated)."""
    for base in (os.path.dirname(including), root, os.path.join(root, "include")):
        candidate = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(candidate) and candidate.startswith(root + os.sep):
            return os.path.relpath(candidate, root)
    return None


def source_files(root):
    for folder, subfolders, files in os.walk(root):
        # Build trees (any name) hold generated sources of no layer.
        subfolders[:] = sorted(s for s in subfolders if s not in SKIPPED_FOLDERS and
                               not os.path.isfile(os.path.join(folder, s, "CMakeCache.txt")))
        for name in sorted(files):
            if name.endswith(SOURCE_SUFFIXES):
                yield os.path.join(folder, name)


def check(root, table, install_list=None):
    """The violations under `root`, as printable lines."""
    root = os.path.abspath(root)
    _, prefixes, deps = read_table(table)
    allowed = allowed_layers(deps)
    problems = []
    for path in source_files(root):
        relative = os.path.relpath(path, root)
        layer = layer_of(relative, prefixes)
        if layer is None:
            problems.append(f"{relative}: in no layer of {os.path.basename(table)}")
            continue
        with open(path, encoding="utf-8", errors="replace") as source:
            for number, line in enumerate(source, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                target = resolve(root, path, match.group(1))
                if target is None:
                    continue
                target_layer = layer_of(target, prefixes)
                if target_layer is None or target_layer not in allowed[layer]:
                    problems.append(f"{relative}:{number}: {layer} includes {target} "
                                    f"({target_layer or 'no layer'})")
    if install_list:
        problems += check_install_list(root, install_list)
    return problems


def check_install_list(root, cmake_file):
    """include/ivshadow/ must hold exactly the headers that `cmake_file` installs."""
    with open(cmake_file, encoding="utf-8") as text:
        installed = set(re.findall(r"include/ivshadow/[A-Za-z0-9_]+\.h", text.read()))
    folder = os.path.join(root, "include", "ivshadow")
    present = set()
    if os.path.isdir(folder):
        present = {f"include/ivshadow/{name}" for name in os.listdir(folder)}
    problems = [f"{name}: in include/ivshadow/ but not installed by "
                f"{os.path.basename(cmake_file)}" for name in sorted(present - installed)]
    problems += [f"{name}: installed but not in include/ivshadow/"
                 for name in sorted(installed - present)]
    return problems


def main(argv):
    args = argv[1:]
    install_list = None
    if "--install-list" in args:
        at = args.index("--install-list")
        install_list = args[at + 1]
        del args[at:at + 2]
    if len(args) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    problems = check(args[0], args[1], install_list)
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} layering violation(s)")
        return 1
    print("layers: every include goes downwards")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
