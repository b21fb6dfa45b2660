#!/usr/bin/env python3
"""The layering check itself: it must pass a tree that only includes downwards and fail on
each kind of violation (upwards, between siblings, into a public header that is not installed)
and refuse a table whose layers are not one folder each. Each case builds a small tree in a
scratch folder."""

import os
import subprocess
import sys
import tempfile
import unittest

CHECKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "check_layers.py")

TABLE = """\
# a small tree shaped like the project's
low      low/                 :
left     left/                : low
right    right/               : low
macros   include/ivshadow/Macros.h :
api      include/ivshadow/    : macros
top      top/                 : api left right
"""

INSTALL = "set(HEADERS include/ivshadow/Api.h include/ivshadow/Macros.h)\n"


class LayerCheckTest(unittest.TestCase):
    def make_tree(self, files):
        scratch = tempfile.TemporaryDirectory(prefix="layers-")
        self.addCleanup(scratch.cleanup)
        root = scratch.name
        base = {
            "layers.txt": TABLE,
            "Install.cmake": INSTALL,
            "low/Low.h": "#pragma once\n#include <vector>\n",
            "left/Left.h": '#pragma once\n#include "low/Low.h"\n',
            "right/Right.h": '#pragma once\n#include "low/Low.h"\n',
            "include/ivshadow/Api.h": '#pragma once\n#include "ivshadow/Macros.h"\n',
            "include/ivshadow/Macros.h": "#pragma once\n",
            "top/Top.cpp": '#include "left/Left.h"\n#include "right/Right.h"\n'
                           '#include <ivshadow/Api.h>\n#include "Generated.h"\n',
        }
        base.update(files)
        for name, text in base.items():
            path = os.path.join(root, name)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as out:
                out.write(text)
        return root

    def run_checker(self, root, *extra):
        result = subprocess.run(
            [sys.executable, CHECKER, root, os.path.join(root, "layers.txt"),
             "--install-list", os.path.join(root, "Install.cmake"), *extra],
            capture_output=True, text=True)
        return result.returncode, result.stdout

    def assert_fails_with(self, files, line):
        status, out = self.run_checker(self.make_tree(files))
        self.assertEqual(status, 1, out)
        self.assertIn(line, out)

    def test_a_tree_that_includes_downwards_passes(self):
        status, out = self.run_checker(self.make_tree({}))
        self.assertEqual(status, 0, out)

    def test_an_upward_include_fails(self):
        self.assert_fails_with(
            {"low/Low.cpp": '#include "low/Low.h"\n#include "top/Top.h"\n',
             "top/Top.h": "#pragma once\n"},
            "low/Low.cpp:2: low includes top/Top.h (top)")

    def test_an_include_between_siblings_fails(self):
        self.assert_fails_with({"right/Right.cpp": '#include "left/Left.h"\n'},
                               "right/Right.cpp:1: right includes left/Left.h (left)")

    def test_an_installed_header_of_its_own_layer_is_below_its_folder(self):
        # include/ivshadow/Macros.h belongs to macros, which may not include the rest of api.
        self.assert_fails_with({"include/ivshadow/Macros.h": '#include "ivshadow/Api.h"\n'},
                               "include/ivshadow/Macros.h:1: macros includes "
                               "include/ivshadow/Api.h (api)")

    def assert_table_refused(self, table, line):
        status, out = self.run_checker(self.make_tree({"layers.txt": table}))
        self.assertEqual(status, 1, out)
        self.assertIn(line, out)

    def test_a_file_as_a_layer_is_refused(self):
        self.assert_table_refused(TABLE + "special  left/Special   : low\n",
                                  "left/Special is not a folder")

    def test_two_folders_for_one_layer_are_refused(self):
        self.assert_table_refused(TABLE.replace("right/ ", "right/ top/"),
                                  "a layer is a name and one folder")

    def test_a_folder_inside_another_layers_folder_is_refused(self):
        self.assert_table_refused(TABLE + "inner    left/inner/     : low\n",
                                  "left/inner/ (inner) lies inside left/ (left)")

    def test_a_file_in_no_layer_fails(self):
        self.assert_fails_with({"stray/Stray.cpp": "\n"}, "stray/Stray.cpp: in no layer")

    def test_a_public_header_that_is_not_installed_fails(self):
        self.assert_fails_with({"include/ivshadow/Private.h": "\n"},
                               "include/ivshadow/Private.h: in include/ivshadow/ but not installed")

    DOCS = ("# Architecture\n\n## The layers\n\n| layer | folder | holds |\n|---|---|---|\n"
            "| low | `low/` | |\n| left, right | `left/`, `right/` | |\n"
            "| macros | `include/ivshadow/Macros.h` | |\n| api | `include/ivshadow/` | |\n"
            "| top | `top/` | |\n\n## Next\n\n| not | `a layer` |\n")

    def test_docs_that_name_each_layer_and_its_folder_pass(self):
        root = self.make_tree({"Docs.md": self.DOCS})
        status, out = self.run_checker(root, "--docs", os.path.join(root, "Docs.md"))
        self.assertEqual(status, 0, out)

    def test_docs_that_miss_a_layer_or_name_another_folder_fail(self):
        docs = self.DOCS.replace("| top | `top/` | |\n", "").replace("`low/`", "`lower/`")
        root = self.make_tree({"Docs.md": docs})
        status, out = self.run_checker(root, "--docs", os.path.join(root, "Docs.md"))
        self.assertEqual(status, 1, out)
        self.assertIn("Docs.md: layer top (top/) is not in its table of layers", out)
        self.assertIn("Docs.md: layer low is lower/, not low/", out)


if __name__ == "__main__":
    unittest.main()
