# SPDX-License-Identifier: MIT
"""What the Python module's tests share: the tools of the same build, the shipped data, a scratch
folder. CTest sets PYTHONPATH (the built module), TRISTREAM_BIN (the tools' folder) and
TRISTREAM_SOURCE_DIR (tests/python/CMakeLists.txt)."""
import json
import os
import subprocess
import tempfile
import unittest
from pathlib import Path

import numpy as np
import tristream

SOURCE = Path(os.environ.get("TRISTREAM_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BIN = Path(os.environ.get("TRISTREAM_BIN", SOURCE / "build" / "bin"))
DEMO = SOURCE / "data" / "demo"
GOLDEN = SOURCE / "tests" / "golden"
# The tools print doubles in full (JSON); the module's figures must equal them to this.
TOLERANCE = 1e-9


def tool(name, *args, check=True):
    """Runs a tool of this build; returns its stdout (text)."""
    run = subprocess.run([str(BIN / name), *map(str, args)], capture_output=True, text=True, check=False)
    if check and run.returncode != 0:
        raise AssertionError(f"{name} {' '.join(map(str, args))}: exit {run.returncode}: {run.stderr}")
    return run.stdout


def tool_json(name, *args):
    return json.loads(tool(name, *args, "--json").strip().splitlines()[-1])


def small_image(width=96, height=64, grey=False):
    """A corner of the demo photograph, small enough to encode in a moment."""
    image = tristream.read_image(DEMO / "kodim23.png")[200:200 + height, 300:300 + width]
    return np.ascontiguousarray(image.mean(axis=2).round().astype(np.uint8) if grey else image)


class ScratchTest(unittest.TestCase):
    """A test with a scratch folder, self.dir, removed afterwards."""

    def setUp(self):
        self._scratch = tempfile.TemporaryDirectory(prefix="tristream-py-")
        self.dir = Path(self._scratch.name)

    def tearDown(self):
        self._scratch.cleanup()

    def assertClose(self, ours, tools, what):
        if tools is None:  # JSON's null: an infinite PSNR
            self.assertEqual(ours, float("inf"), what)
            return
        self.assertLessEqual(abs(ours - tools), TOLERANCE, f"{what}: module {ours!r}, tool {tools!r}")
