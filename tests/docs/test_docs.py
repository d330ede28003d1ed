#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Figures and names the documentation quotes, checked against the code they describe.

Run: /usr/bin/python3 -m unittest discover -s tests/docs -v (ctest runs it as test_docs).
Each test reads the files as they are; none needs a build.
"""
import re
import subprocess
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DOCS = [ROOT / "README.md", ROOT / "CONTRIBUTING.md", *sorted((ROOT / "docs").glob("*.md")),
        *sorted(ROOT.glob("tools/*/README.md")), ROOT / "tests/golden/README.md"]
TOP_DIRS = ("host_sim/", "firmware_core/", "tools/", "tests/", "docs/", "data/", "cmake/", ".ci/", "ports/", "zephyr/", "python/", "examples/")


def read(rel):
    return (ROOT / rel).read_text(encoding="utf-8")


def c_default(header, macro):
    """The default value of `#define MACRO value` in a config header."""
    m = re.search(rf"#define {macro} (\S+)", read(header))
    if not m:
        raise AssertionError(f"{header}: no #define {macro}")
    return int(m.group(1), 0)


class ReadmeCiList(unittest.TestCase):
    def test_readme_names_every_ci_step(self):
        steps = re.findall(r"^make ([\w-]+)", read(".ci/run"), re.M)
        self.assertTrue(steps, ".ci/run: no make steps found")
        m = re.search(r"CI \(`\.ci/run`\) runs (.*?)\.\n\n", read("README.md"), re.S)
        self.assertIsNotNone(m, "README.md: no sentence 'CI (`.ci/run`) runs ...'")
        listed = re.findall(r"`make ([\w-]+)`", m.group(1))
        self.assertEqual(listed, steps, "README.md's CI list differs from .ci/run's steps")


class NoMergeMarkers(unittest.TestCase):
    def test_no_conflict_markers_in_tracked_files(self):
        files = subprocess.run(["git", "-C", str(ROOT), "ls-files", "-z"], capture_output=True,
                               check=True).stdout.decode().split("\0")
        marked = []
        for name in filter(None, files):
            path = ROOT / name
            if not path.is_file():
                continue
            try:
                text = path.read_text(encoding="utf-8")
            except UnicodeDecodeError:
                continue  # binary data
            if re.search(r"^(<{7}|>{7}) ", text, re.M):
                marked.append(name)
        self.assertEqual(marked, [], "merge conflict markers left in these files")


def tracked(*prefixes):
    """Tracked files under these folders (git ls-files), as paths relative to ROOT."""
    out = subprocess.run(["git", "-C", str(ROOT), "ls-files", "-z", "--", *prefixes], capture_output=True,
                         check=True).stdout.decode().split("\0")
    return [name for name in out if name and (ROOT / name).is_file()]


class ArchitectureMap(unittest.TestCase):
    def test_every_core_file_is_on_the_map(self):
        """docs/ARCHITECTURE.md names every source and header of firmware_core (src/ and include/)."""
        text = read("docs/ARCHITECTURE.md")
        def shown(name):  # src/ files by their path under src/, headers as they are included
            rel = Path(name).relative_to("firmware_core")
            return "/".join(rel.parts[1:])
        missing = [name for name in tracked("firmware_core/src", "firmware_core/include")
                   if f"`{shown(name)}`" not in text]
        self.assertEqual(missing, [], "docs/ARCHITECTURE.md does not name these core files")


class NoDevelopmentLog(unittest.TestCase):
    """The core's comments and docs/ state what is true now and why: no session numbers or commit
    hashes (figures go to docs/MCU_BENCH.md, stated as of a version)."""

    def test_no_session_numbers_or_commit_hashes(self):
        session = re.compile(r"\bsessions? \d+|\bsession's\b", re.I)
        commit = re.compile(r"(?<![0-9A-Za-z_])(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}(?![0-9A-Za-z_])")
        found = []
        for name in tracked("firmware_core", "docs"):
            try:
                text = (ROOT / name).read_text(encoding="utf-8")
            except UnicodeDecodeError:
                continue
            for number, line in enumerate(text.splitlines(), 1):
                if session.search(line) or (commit.search(line) and "0x" not in line):
                    found.append(f"{name}:{number}: {line.strip()[:80]}")
        self.assertEqual(found, [], "development history in the core or docs/")


class PathsExist(unittest.TestCase):
    def test_every_quoted_repository_path_exists(self):
        missing = []
        for doc in DOCS:
            if not doc.exists():
                continue
            for token in re.findall(r"`([^`\s]+)`", doc.read_text(encoding="utf-8")):
                path = token.split(":")[0].rstrip(".,")
                if not path.startswith(TOP_DIRS) or re.search(r"[<>*$\[{]", path):
                    continue
                if not (ROOT / path).exists():
                    missing.append(f"{doc.relative_to(ROOT)}: {token}")
        self.assertEqual(missing, [], "paths quoted in the docs that do not exist")


# Paths of one machine or of folders beside the repository, spelled in pieces so that this file,
# which the check skips anyway, holds none of them whole.
OUTSIDE_PATHS = ["/" + "work/", ".." + "/shared", "shared" + "/images", "shared" + "/reference"]


class StandsAlone(unittest.TestCase):
    def test_no_machine_paths(self):
        # Nothing may depend on one machine's files or on a folder beside the repository.
        try:
            files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                                   check=True).stdout.split()
        except (OSError, subprocess.CalledProcessError):
            self.skipTest("not a git checkout")
        bad = []
        for rel in files:
            path = ROOT / rel
            if rel.startswith("tests/docs/") or path.suffix in {".png", ".bin", ".tri"} or not path.is_file():
                continue
            try:
                text = path.read_text(encoding="utf-8")
            except UnicodeDecodeError:
                continue
            for n, line in enumerate(text.splitlines(), 1):
                if any(p in line for p in OUTSIDE_PATHS):
                    bad.append(f"{rel}:{n}: {line.strip()}")
        self.assertEqual(bad, [], "paths outside the repository")


class FixedPointFigures(unittest.TestCase):
    def test_position_range_follows_config(self):
        d = c_default("firmware_core/include/tristream/config.h", "TS_MAX_DIMENSION")
        s = c_default("firmware_core/include/tristream/config.h", "TS_SUBPIXEL_BITS")
        text = read("docs/FIXED_POINT.md")
        for quoted in [f"(D-1) * 2^S = {(d - 1) * 2 ** s}", f"D * 2^S = 2^{(d * 2 ** s).bit_length() - 1}"]:
            self.assertTrue(quoted in text, f"docs/FIXED_POINT.md does not say {quoted!r}")
        self.assertEqual(d * 2 ** s, 2 ** ((d * 2 ** s).bit_length() - 1), "D * 2^S is no longer a power of two")

    def test_divider_correction_count(self):
        # The reciprocal division corrects its estimate once: the doc and the code's comment agree.
        self.assertIn("at most\n// one correction", read("firmware_core/src/arith.h"))
        text = read("docs/FIXED_POINT.md")
        self.assertTrue("high multiply with one correction" in text, "docs/FIXED_POINT.md: Divider's correction")
        # PreinvRoundingDivider (Cortex-M) does correct up to twice; the Divider's own sentence must not say so.
        divider = text[text.index("high multiply with one correction") - 400 : text.index("`Divider`") + 12]
        self.assertFalse("two corrections" in divider, "docs/FIXED_POINT.md says two corrections of Divider")


class ConventionsMatchCode(unittest.TestCase):
    def test_ycbcr_coefficients(self):
        code = read("host_sim/model/color.h")
        doc = " ".join(read("docs/CONVENTIONS.md").split())
        numbers = [float(x) for x in re.findall(r"\d\.\d+", code)]
        for c in ["0.299", "0.587", "0.114", "0.168736", "0.331264", "0.418688", "0.081312", "1.402",
                  "0.344136", "0.714136", "1.772"]:
            self.assertIn(c, doc)
            places = len(c.split(".")[1])
            self.assertTrue(any(round(x, places) == float(c) for x in numbers),
                            f"CONVENTIONS.md's {c} is no coefficient of color.h")

    def test_ssim_defaults(self):
        code = read("host_sim/metrics/metrics.h")
        doc = " ".join(read("docs/CONVENTIONS.md").split())
        self.assertRegex(code, r"double k1 = 0\.01;")
        self.assertRegex(code, r"double k2 = 0\.03;")
        self.assertIn("sigma 1.5", code)
        for quoted in ["11 x 11 Gaussian window, σ = 1.5, K1 = 0.01, K2 = 0.03", "population"]:
            self.assertIn(quoted, doc)


if __name__ == "__main__":
    unittest.main()
