# SPDX-License-Identifier: MIT
"""cmake --install puts the module where README says, and it imports and works from there; the
example script runs (items: install, example). TRISTREAM_BUILD_DIR names the build."""
import os
import subprocess
import sys
import unittest
from pathlib import Path

import tristream

from support import SOURCE, ScratchTest


class Install(ScratchTest):
    def test_installed_module_imports(self):
        build = Path(os.environ["TRISTREAM_BUILD_DIR"])
        prefix = self.dir / "prefix"
        subprocess.run(["cmake", "--install", str(build), "--component", "python", "--prefix", str(prefix)],
                       check=True, capture_output=True)
        site = prefix / "lib" / f"python{sys.version_info.major}.{sys.version_info.minor}" / "dist-packages"
        modules = list(site.glob("tristream*.so"))
        self.assertEqual(len(modules), 1, f"no module under {site}")
        env = dict(os.environ, PYTHONPATH=str(site))
        code = ("import tristream, sys; t = tristream.read_tri(sys.argv[1]); "
                "print(tristream.__file__, tristream.__version__, t.width)")
        run = subprocess.run([sys.executable, "-c", code, str(SOURCE / "tests/golden/grey.tri")], env=env,
                             capture_output=True, text=True, check=True)
        self.assertIn(str(site), run.stdout)
        self.assertIn(f"{tristream.__version__} 192", run.stdout)


class Example(ScratchTest):
    def test_quickstart_runs(self):
        run = subprocess.run([sys.executable, str(SOURCE / "examples/python_quickstart.py"), str(self.dir)],
                             capture_output=True, text=True, check=False)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertRegex(run.stdout, r"bilinear +PSNR +\d+\.\d+ dB")
        self.assertRegex(run.stdout, r"zienkiewicz +PSNR +\d+\.\d+ dB")
        self.assertTrue((self.dir / "kodim23.tri").is_file())
        self.assertEqual(tristream.read_tri(self.dir / "kodim23.tri").vertices.shape, (2000, 2))


if __name__ == "__main__":
    unittest.main()
