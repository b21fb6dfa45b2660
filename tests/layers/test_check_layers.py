#!/usr/bin/env python3
"""The layering check itself: it must pass a tree that only includes downwards and fail on
each kind of violation (upwards, between siblings, from a file-level layer, into a public
header that is not installed). Each case builds a small tree in a scratch folder."""

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
api      include/ivshadow/         :
top      top/ left/Special    : api left right
"""

INSTALL = "set(HEADERS include/ivshadow/Api.h)\n"


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
            "include/ivshadow/Api.h": "#pragma once\n",
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

    def run_checker(self, root):
        result = subprocess.run(
            [sys.executable, CHECKER, root, os.path.join(root, "layers.txt"),
             "--install-list", os.path.join(root, "Install.cmake")],
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

    def test_a_file_level_layer_is_above_its_folder(self):
        # left/Special belongs to top, so the rest of left/ may not include it.
        self.assert_fails_with(
            {"left/Special.h": "#pragma once\n", "left/Left.cpp": '#include "left/Special.h"\n'},
            "left/Left.cpp:1: left includes left/Special.h (top)")

    def test_a_file_in_no_layer_fails(self):
        self.assert_fails_with({"stray/Stray.cpp": "\n"}, "stray/Stray.cpp: in no layer")

    def test_a_public_header_that_is_not_installed_fails(self):
        self.assert_fails_with({"include/ivshadow/Private.h": "\n"},
                               "include/ivshadow/Private.h: in include/ivshadow/ but not installed")


if __name__ == "__main__":
    unittest.main()
