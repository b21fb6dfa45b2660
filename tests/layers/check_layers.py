#!/usr/bin/env python3
"""Fails when a file of the project includes a file of a layer it may not depend on.

Usage: check_layers.py ROOT TABLE [--install-list FILE] [--docs FILE]

ROOT is the source tree, TABLE the layer table (tests/layers/layers.txt describes the format):
one folder per layer, and a table that names a file instead (but an installed header) or two
folders for a layer is refused.
Every #include of a .h or .cpp file under ROOT that names a file of the project (looked up
beside the including file, from ROOT, and from ROOT/include) must stay within what the
including file's layer may use. With --install-list, the headers under include/ivshadow/ must
be exactly those the CMake file lists (the public API is the installed set, nothing else).
With --docs, the markdown table under "## The layers" of FILE (docs/ARCHITECTURE.md) must name
each layer with its folder, and no other: "| gl | `gl/` | ... |", or several layers in a row
with their folders in the same order.
Prints one line per violation and exits 1 if there is any.
"""

import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')
SOURCE_SUFFIXES = (".h", ".cpp")
SKIPPED_FOLDERS = {".git", "build"}
# The installed headers' paths are the public API, so a header there may be a layer of its own
# (include/ivshadow/Export.h); anywhere else a layer is a folder.
INSTALLED = "include/"


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
            raise ValueError(f"{path}:{number}: expected 'layer folder : deps...'")
        left, right = line.split(":", 1)
        words = left.split()
        if len(words) != 2:
            raise ValueError(f"{path}:{number}: a layer is a name and one folder, not "
                             f"{' '.join(words) or 'nothing'}")
        layer, folder = words
        if layer in deps:
            raise ValueError(f"{path}:{number}: layer {layer} is named twice")
        if not folder.endswith("/") and not folder.startswith(INSTALLED):
            raise ValueError(f"{path}:{number}: {folder} is not a folder: a layer is a folder "
                             f"(only an installed header, whose path is the API, stands alone)")
        if folder in prefixes:
            raise ValueError(f"{path}:{number}: {folder} is the folder of {prefixes[folder]} too")
        order.append(layer)
        prefixes[folder] = layer
        deps[layer] = set(right.split())
    folders = [p for p in prefixes if p.endswith("/")]
    for inner in folders:
        for outer in folders:
            if inner != outer and inner.startswith(outer):
                raise ValueError(f"{path}: {inner} ({prefixes[inner]}) lies inside {outer} "
                                 f"({prefixes[outer]}): one folder per layer")
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
    best = None
    for prefix, layer in prefixes.items():
        matches = relative.startswith(prefix) if prefix.endswith("/") else relative == prefix
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


def check_docs(table, docs):
    """The layers and folders the docs' table of layers names must be the table's."""
    _, prefixes, _ = read_table(table)
    want = {layer: folder for folder, layer in prefixes.items()}
    said, problems, inside = {}, [], False
    with open(docs, encoding="utf-8") as text:
        for number, line in enumerate(text, 1):
            if line.startswith("## "):
                inside = line.strip() == "## The layers"
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if not inside or not line.startswith("|") or len(cells) < 2:
                continue
            names = [n.strip() for n in cells[0].split(",")]
            folders = re.findall(r"`([^`]+)`", cells[1])
            if names == ["layer"] or set(cells[0]) <= set("-: "):
                continue  # the header and its rule
            if len(names) != len(folders):
                problems.append(f"{os.path.basename(docs)}:{number}: {len(names)} layers, "
                                f"{len(folders)} folders")
                continue
            said.update(zip(names, folders))
    for layer in sorted(set(want) | set(said)):
        if layer not in said:
            problems.append(f"{os.path.basename(docs)}: layer {layer} ({want[layer]}) is not in "
                            f"its table of layers")
        elif layer not in want:
            problems.append(f"{os.path.basename(docs)}: layer {layer} is in no "
                            f"{os.path.basename(table)}")
        elif said[layer] != want[layer]:
            problems.append(f"{os.path.basename(docs)}: layer {layer} is {said[layer]}, not "
                            f"{want[layer]} as {os.path.basename(table)} says")
    return problems


def main(argv):
    args = argv[1:]
    install_list = docs = None
    if "--install-list" in args:
        at = args.index("--install-list")
        install_list = args[at + 1]
        del args[at:at + 2]
    if "--docs" in args:
        at = args.index("--docs")
        docs = args[at + 1]
        del args[at:at + 2]
    if len(args) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    try:
        problems = check(args[0], args[1], install_list)
        if docs:
            problems += check_docs(args[1], docs)
    except ValueError as error:
        print(error)
        return 1
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} layering violation(s)")
        return 1
    print("layers: every include goes downwards")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
