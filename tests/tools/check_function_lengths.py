#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""No host function over 120 lines: every C and C++ function definition (lambdas included) in
host_sim/, tools/ and python/ (the Python module), as universal-ctags finds it, from its first line to its last. The files of
ALLOWED are left out while their long functions are rewritten; when one has none left, the check
says so, and it leaves the list.

Usage: check_function_lengths.py <source dir> [ctags program]. Exit 0 when none is too long, 1
with one line per function ("path:line: name is N lines, over 120"), 2 when ctags is missing, is
not universal-ctags or finds no function."""
import fnmatch
import json
import subprocess
import sys

LIMIT = 120
ROOTS = ["host_sim", "tools", "python"]
ALLOWED = []  # every host function is within the limit


def functions(source, ctags):
    """(path, line, end, name) of every function definition under ROOTS."""
    try:
        version = subprocess.run([ctags, "--version"], capture_output=True, text=True, check=False).stdout
    except FileNotFoundError:
        version = ""
    if "Universal Ctags" not in version:
        print(f"check_function_lengths: expected universal-ctags as '{ctags}' (tools/install-deps.sh checks)",
              file=sys.stderr)
        sys.exit(2)
    out = subprocess.run(
        [ctags, "-x", "--languages=C,C++", "--kinds-C=f", "--kinds-C++=f", "--fields=+ne",
         "--output-format=json", "-R", *ROOTS],
        cwd=source, capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        tag = json.loads(line)
        if tag.get("_type") == "tag" and "end" in tag:
            yield tag["path"], tag["line"], tag["end"], tag["name"]


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    source = sys.argv[1]
    ctags = sys.argv[2] if len(sys.argv) == 3 else "ctags"
    too_long, allowed_long, count = [], set(), 0
    for path, line, end, name in functions(source, ctags):
        count += 1
        lines = end - line + 1
        if lines <= LIMIT:
            continue
        if any(fnmatch.fnmatch(path, pattern) for pattern in ALLOWED):
            allowed_long.add(path)
            continue
        too_long.append(f"{path}:{line}: {name} is {lines} lines, over {LIMIT}")
    if count == 0:
        print(f"check_function_lengths: no functions found under {source}/{{{','.join(ROOTS)}}}", file=sys.stderr)
        return 2
    for pattern in ALLOWED:
        if not any(fnmatch.fnmatch(path, pattern) for path in allowed_long):
            print(f"note: {pattern} has no function over {LIMIT} lines: it can leave ALLOWED")
    for message in too_long:
        print(message)
    print(f"{count} functions, {len(too_long)} over {LIMIT} lines")
    return 1 if too_long else 0


if __name__ == "__main__":
    sys.exit(main())
