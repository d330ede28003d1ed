#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Checks that a report page renders in a real browser: headless Chromium (Debian's chromium)
loads a copy of the page with a probe script, and the page passes when no script or resource
error was raised and every <img> decoded to a non-zero natural size.

Usage: check_page.py PAGE.html [--figures DIR...] [--screenshot OUT.png] [--height PIXELS]

With --figures, every .png and .jpg in those folders must be shown on the page (figures name
their file in a <span class=file> of the caption, as report.py writes them).

Prints one line per problem and exits 0 when there is none, 65 when the page has problems, 66
when the page or chromium is missing, 70 when chromium fails. The probe runs on a temporary copy;
the page itself is not changed.
"""
import argparse
import html.parser
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

EXIT_DATA, EXIT_NOINPUT, EXIT_SOFTWARE = 65, 66, 70
BROWSERS = ("chromium", "chromium-browser")
# Marks each image with what the browser made of it, and the body with the errors raised while
# loading (resource errors reach window only in the capture phase).
PROBE = """<script>
window.__errors = [];
window.addEventListener('error', function (e) {
  var t = e.target;
  window.__errors.push(t && t.tagName ? ('cannot load <' + t.tagName.toLowerCase() + '> ' +
      (t.alt || (t.src || '').slice(0, 60))) : ('script error: ' + e.message));
}, true);
window.addEventListener('load', function () {
  var imgs = document.images;
  for (var i = 0; i < imgs.length; i++) {
    var ok = imgs[i].complete && imgs[i].naturalWidth > 0 && imgs[i].naturalHeight > 0;
    imgs[i].setAttribute('data-probe', ok ? 'ok ' + imgs[i].naturalWidth + 'x' + imgs[i].naturalHeight : 'broken');
    var figure = imgs[i].closest('figure'), file = figure && figure.querySelector('.file');
    if (file) imgs[i].setAttribute('data-file', file.textContent.replace(/[()]/g, ''));
  }
  var out = document.createElement('pre');
  out.id = '__probe';
  out.textContent = JSON.stringify({images: imgs.length, errors: window.__errors});
  document.body.appendChild(out);
});
</script>"""


def browser():
    for name in BROWSERS:
        path = shutil.which(name)
        if path:
            return path
    return None


def run_browser(exe, args, env, timeout=180):
    # --no-sandbox: Chromium refuses to run as root otherwise (CI containers run as root).
    cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--mute-audio",
           "--no-first-run", "--disable-dev-shm-usage", "--virtual-time-budget=20000"] + args
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)


class ProbeResult(html.parser.HTMLParser):
    """The images' probe marks and the probe's summary, from the DOM Chromium dumps."""

    def __init__(self):
        super().__init__()
        self.images = []  # (alt, probe mark or None, figure file name or None)
        self.summary = None
        self._in_probe = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "img":
            self.images.append((a.get("alt") or (a.get("src") or "")[:60], a.get("data-probe"), a.get("data-file")))
        if tag == "pre" and a.get("id") == "__probe":
            self._in_probe = True
            self.summary = ""

    def handle_endtag(self, tag):
        if tag == "pre":
            self._in_probe = False

    def handle_data(self, data):
        if self._in_probe:
            self.summary += data


def check(page: Path, screenshot=None, height=2400, figures=()):
    """(problems found, images on the page); no problems: the page renders, and every figure
    file in the folders `figures` is shown. Raises FileNotFoundError without chromium,
    RuntimeError when chromium fails."""
    import json
    exe = browser()
    if exe is None:
        raise FileNotFoundError("chromium is not installed (Debian package chromium: "
                                "tools/install-deps.sh browser)")
    text = page.read_text(encoding="utf-8")
    # The probe goes first, so that it sees the errors of every script after it.
    head = text.find("<head>")
    probed = text[:head + 6] + PROBE + text[head + 6:] if head >= 0 else PROBE + text
    with tempfile.TemporaryDirectory() as d:
        copy = Path(d) / page.name
        copy.write_text(probed, encoding="utf-8")
        # The report embeds its figures as data URIs; its relative links (CSV files) are not loaded.
        env = {**os.environ, "HOME": d}  # chromium writes its profile and caches under HOME
        dom = run_browser(exe, ["--user-data-dir=" + str(Path(d) / "profile"), "--dump-dom", copy.as_uri()], env)
        if dom.returncode != 0 or "<html" not in dom.stdout:
            raise RuntimeError(f"chromium --dump-dom exit {dom.returncode}: {dom.stderr.strip()[-400:]}")
        if screenshot:
            shot = run_browser(exe, ["--user-data-dir=" + str(Path(d) / "profile2"), f"--window-size=1280,{height}",
                                     "--screenshot=" + str(Path(screenshot).resolve()), page.resolve().as_uri()], env)
            if shot.returncode != 0 or not Path(screenshot).exists():
                raise RuntimeError(f"chromium --screenshot exit {shot.returncode}: {shot.stderr.strip()[-400:]}")
    parser = ProbeResult()
    parser.feed(dom.stdout)
    problems = []
    if parser.summary is None:
        return ["the probe did not run: the page's load event never fired"], len(parser.images)
    summary = json.loads(parser.summary)
    problems += summary["errors"]
    for alt, mark, _ in parser.images:
        if not (mark or "").startswith("ok"):
            problems.append(f"image not shown: {alt}")
    shown = {name for _, mark, name in parser.images if (mark or "").startswith("ok")}
    for folder in figures:
        for f in sorted(Path(folder).iterdir()):
            if f.suffix in (".png", ".jpg") and f.name not in shown:
                problems.append(f"figure not on the page: {f}")
    if not parser.images:
        problems.append("the page has no images")
    return problems, len(parser.images)


def main(argv):
    p = argparse.ArgumentParser(prog="check_page.py", description=__doc__.split("\n\n")[0])
    p.add_argument("page", type=Path)
    p.add_argument("--figures", type=Path, nargs="*", default=[], help="folders whose figures must all be shown")
    p.add_argument("--screenshot", type=Path, help="also write a screenshot of the page's top")
    p.add_argument("--height", type=int, default=2400, help="screenshot height in pixels (width 1280)")
    args = p.parse_args(argv)
    if not args.page.is_file():
        print(f"check_page: {args.page}: no such file", file=sys.stderr)
        return EXIT_NOINPUT
    try:
        problems, images = check(args.page, args.screenshot, args.height, args.figures)
    except FileNotFoundError as exc:
        print(f"check_page: {exc}", file=sys.stderr)
        return EXIT_NOINPUT
    except (RuntimeError, subprocess.TimeoutExpired) as exc:
        print(f"check_page: {args.page}: {exc}", file=sys.stderr)
        return EXIT_SOFTWARE
    for problem in problems:
        print(f"check_page: {args.page}: {problem}", file=sys.stderr)
    if problems:
        return EXIT_DATA
    print(f"check_page: {args.page}: renders in chromium without errors, all {images} images shown")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
