#!/usr/bin/env bash
# Lists the source files (C, C++, assembly, linker scripts, CMake, shell, Python, Makefiles; scripts by their #! line) tracked by git that lack a
# "SPDX-License-Identifier: MIT" line in their first five lines, and exits 1 if there is any.
# Data, documentation and generated files are not checked, nor Arduino's build_opt.h (compiler options).
# Usage: tools/check-spdx.sh [REPO_DIR]   (default: the repository this script is in)
set -euo pipefail
root=$(cd "${1:-$(dirname "$0")/..}" && pwd)
cd "$root"
git rev-parse --is-inside-work-tree >/dev/null 2>&1 || { echo "check-spdx: $root is not a git work tree" >&2; exit 66; }

missing=0
checked=0
while IFS= read -r -d '' file; do
  case "$file" in
    */build_opt.h) continue ;;  # Arduino's file of compiler options: no line may be a comment
    *.c | *.h | *.cpp | *.hpp | *.cc | *.S | *.ld | *.cmake | */CMakeLists.txt | CMakeLists.txt | *.sh | *.py | Makefile | */Makefile | *.mk) ;;
    *)  # scripts without an extension, such as .ci/run, by their #! line
      [ -f "$file" ] && head -n 1 "$file" | grep -Eq '^#!.*(sh|python)' || continue ;;
  esac
  [ -f "$file" ] || continue
  checked=$((checked + 1))
  if ! head -n 5 "$file" | grep -q 'SPDX-License-Identifier: MIT'; then
    echo "$file"
    missing=$((missing + 1))
  fi
done < <(git ls-files -z)

if [ $missing -gt 0 ]; then
  echo "check-spdx: $missing of $checked source files lack 'SPDX-License-Identifier: MIT'" >&2
  exit 1
fi
echo "check-spdx: all $checked source files carry 'SPDX-License-Identifier: MIT'"
