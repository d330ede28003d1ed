#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The browser check of the report page (tools/experiments/check_page.py) in headless Chromium:
it passes a page whose images all decode and fails one with a broken image, a script error or a
figure file missing from the page. Skips when chromium is not installed (tools/install-deps.sh
browser); `make experiments-quick` runs the same check on the real report."""
import shutil
import sys
import tempfile
import unittest
from pathlib import Path

sys.dont_write_bytecode = True
REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tools/experiments"))

import check_page  # noqa: E402



def tiny_png():
    """A 2 x 1 RGB PNG (a red and a blue pixel)."""
    import struct
    import zlib

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 1, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(bytes([0, 255, 0, 0, 0, 0, 255]))) + chunk(b"IEND", b""))


PNG = tiny_png()


def figure(name, data):
    import base64
    return (f'<figure><img src="data:image/png;base64,{base64.b64encode(data).decode()}" alt="{name}">'
            f'<figcaption>{name} <span class=file>({name})</span></figcaption></figure>')


@unittest.skipUnless(check_page.browser(), "chromium not installed (tools/install-deps.sh browser)")
class ReportPageTest(unittest.TestCase):
    def page(self, body, figures=()):
        d = Path(tempfile.mkdtemp())
        self.addCleanup(shutil.rmtree, d)
        (d / "charts").mkdir()
        for name in figures:
            (d / "charts" / name).write_bytes(PNG)
        p = d / "index.html"
        p.write_text(f"<!DOCTYPE html><html><head><meta charset=utf-8></head><body>{body}</body></html>")
        return p, d / "charts"

    def test_a_page_whose_figures_decode_passes(self):
        p, charts = self.page(figure("a.png", PNG) + figure("b.png", PNG), ["a.png", "b.png"])
        problems, images = check_page.check(p, figures=[charts])
        self.assertEqual((problems, images), ([], 2))

    def test_a_broken_image_fails(self):
        p, _ = self.page(figure("a.png", PNG) + figure("bad.png", PNG[:40]))
        problems, _ = check_page.check(p)
        self.assertTrue(any("bad.png" in x for x in problems), problems)

    def test_a_script_error_fails(self):
        p, _ = self.page(figure("a.png", PNG) + "<script>undefined_function();</script>")
        problems, _ = check_page.check(p)
        self.assertTrue(any("script error" in x for x in problems), problems)

    def test_a_figure_missing_from_the_page_fails(self):
        p, charts = self.page(figure("a.png", PNG), ["a.png", "b.png"])
        problems, _ = check_page.check(p, figures=[charts])
        self.assertEqual(problems, [f"figure not on the page: {charts / 'b.png'}"])

    def test_the_screenshot_is_written(self):
        p, _ = self.page(figure("a.png", PNG))
        shot = p.parent / "shot.png"
        check_page.check(p, screenshot=shot, height=300)
        self.assertTrue(shot.read_bytes().startswith(b"\x89PNG"))


class BrowserCommandTest(unittest.TestCase):
    """Chromium refuses to start as root without --no-sandbox ("Running as root without
    --no-sandbox is not supported"), and CI runs as root: every browser run of the check passes
    it. Runs without chromium (the command is recorded, not run)."""

    def test_every_run_is_headless_without_the_sandbox(self):
        from unittest import mock
        calls = []

        def fake_run(cmd, **kwargs):
            calls.append(cmd)
            return mock.Mock(returncode=0, stdout="<html></html>", stderr="")
        with mock.patch.object(check_page.subprocess, "run", fake_run):
            check_page.run_browser("/usr/bin/chromium", ["--dump-dom", "file:///x.html"], env={})
        self.assertEqual(len(calls), 1)
        self.assertIn("--headless", calls[0])
        self.assertIn("--no-sandbox", calls[0])
        self.assertEqual(calls[0][0], "/usr/bin/chromium")
        self.assertEqual(calls[0][-2:], ["--dump-dom", "file:///x.html"])


if __name__ == "__main__":
    unittest.main()
