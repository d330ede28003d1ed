# SPDX-License-Identifier: MIT
"""Running triencode and trisim with a cache of results keyed by their inputs.

Every cached item is keyed by the SHA-256 of a JSON description of everything it depends on:
the bytes of the input image or .tri file, the command-line options and the bytes of the tool
that computes it. A rebuilt tool or a changed image therefore recomputes only what it affects.
"""
import hashlib
import json
import os
import re
import subprocess
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Dict, List, Optional

EXIT_USAGE = 64


class ToolError(Exception):
    pass


def atomic_write_bytes(path: Path, data: bytes):
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix="." + path.name + ".", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes 0600; give the usual file mode
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise


def atomic_write_text(path: Path, text: str):
    atomic_write_bytes(path, text.encode("utf-8"))


def atomic_write_json(path: Path, obj):
    atomic_write_text(path, json.dumps(obj, indent=1, sort_keys=True) + "\n")


_hash_lock = threading.Lock()
_hash_memo: Dict[tuple, str] = {}


def file_sha256(path: Path) -> str:
    path = Path(path)
    st = path.stat()
    memo_key = (str(path.resolve()), st.st_size, st.st_mtime_ns)
    with _hash_lock:
        if memo_key in _hash_memo:
            return _hash_memo[memo_key]
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    digest = h.hexdigest()
    with _hash_lock:
        _hash_memo[memo_key] = digest
    return digest


def key_of(description: dict) -> str:
    return hashlib.sha256(json.dumps(description, sort_keys=True).encode()).hexdigest()


@dataclass
class Tools:
    bin_dir: Path
    trisim: Path = field(init=False)
    triencode: Path = field(init=False)
    trisim_sha: str = field(init=False)
    triencode_sha: str = field(init=False)
    methods: List[str] = field(init=False)
    engines: List[str] = field(init=False)

    def __post_init__(self):
        self.bin_dir = Path(self.bin_dir)
        self.trisim = self.bin_dir / "trisim"
        self.triencode = self.bin_dir / "triencode"
        for tool in (self.trisim, self.triencode):
            if not (tool.is_file() and os.access(tool, os.X_OK)):
                raise ToolError(f"{tool}: expected an executable (build it with 'make tools'), found none")
        self.trisim_sha = file_sha256(self.trisim)
        self.triencode_sha = file_sha256(self.triencode)
        help_text = self._help(["compare", "--help"])
        self.methods = [m for m in self._choices(help_text, "--method") if m != "all"]
        self.engines = self._choices(help_text, "--engine") or ["reference"]
        if not self.methods:
            raise ToolError(f"{self.trisim} compare --help: expected a list of methods in '--method TEXT:{{...}}', "
                            f"found none")

    def _help(self, args):
        p = subprocess.run([str(self.trisim)] + args, capture_output=True, text=True)
        if p.returncode != 0:
            raise ToolError(f"{self.trisim} {' '.join(args)}: exit {p.returncode}: {p.stderr.strip()}")
        return p.stdout

    @staticmethod
    def _choices(help_text, option):
        m = re.search(re.escape(option) + r"\s+TEXT:\{([^}]*)\}", help_text)
        return [c.strip() for c in m.group(1).split(",")] if m else []


def run_tool(args, timeout=None):
    """Runs a tool; returns (exit code, stdout, stderr, the child's user+system CPU seconds).

    The CPU time comes from os.wait4 on the child, so concurrent workers do not mix theirs."""
    with tempfile.TemporaryFile() as fout, tempfile.TemporaryFile() as ferr:
        proc = subprocess.Popen([str(a) for a in args], stdout=fout, stderr=ferr)
        deadline = None if timeout is None else time.monotonic() + timeout
        status, usage = None, None
        while True:
            pid, st, ru = os.wait4(proc.pid, os.WNOHANG)
            if pid == proc.pid:
                status, usage = st, ru
                break
            if deadline is not None and time.monotonic() > deadline:
                proc.kill()
                pid, st, ru = os.wait4(proc.pid, 0)
                status, usage = st, ru
                break
            time.sleep(0.01)
        proc.returncode = os.waitstatus_to_exitcode(status)
        fout.seek(0)
        ferr.seek(0)
        out = fout.read().decode("utf-8", "replace")
        err = ferr.read().decode("utf-8", "replace")
        cpu = usage.ru_utime + usage.ru_stime
        if deadline is not None and time.monotonic() > deadline and proc.returncode < 0:
            err += f"\n(timed out after {timeout} s)"
        return proc.returncode, out, err, cpu


def first_line(text: str) -> str:
    for line in (text or "").splitlines():
        if line.strip():
            return line.strip()[:400]
    return ""


class Cache:
    def __init__(self, root: Path, force: bool, offline: bool = False):
        self.root = Path(root)
        self.force = force
        self.offline = offline   # report from the cache only: compute nothing
        self.fresh_keys = set()  # keys computed in this run (so --force recomputes each once)
        self.lock = threading.Lock()

    def path(self, kind: str, key: str, suffix: str) -> Path:
        return self.root / kind / key[:2] / (key + suffix)

    def load(self, kind: str, key: str) -> Optional[dict]:
        p = self.path(kind, key, ".json")
        if self.force and key not in self.fresh_keys and not self.offline:
            return None
        try:
            with open(p, "r", encoding="utf-8") as f:
                return json.load(f)
        except (FileNotFoundError, json.JSONDecodeError):
            return None

    def store(self, kind: str, key: str, obj: dict):
        atomic_write_json(self.path(kind, key, ".json"), obj)
        with self.lock:
            self.fresh_keys.add(key)
