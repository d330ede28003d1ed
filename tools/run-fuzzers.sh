#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs each libFuzzer binary in BIN_DIR for SECONDS seconds, starting from a scratch copy of
# its shipped corpus (tests/fuzz/corpus/<kind>), so the repository is never modified.
# Usage: tools/run-fuzzers.sh BIN_DIR SECONDS
set -euo pipefail
bin=$(cd "${1:?usage: run-fuzzers.sh BIN_DIR SECONDS}" && pwd)
seconds=${2:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
found=0
for fuzzer in "$bin"/fuzz_*; do
  [ -x "$fuzzer" ] || continue
  found=1
  name=$(basename "$fuzzer")
  kind=${name#fuzz_}; kind=${kind%%_*}
  mkdir -p "$scratch/$name"
  [ -d "$root/tests/fuzz/corpus/$kind" ] && cp -r "$root/tests/fuzz/corpus/$kind/." "$scratch/$name/"
  dict=()
  [ -f "$root/tests/fuzz/$kind.dict" ] && dict=(-dict="$root/tests/fuzz/$kind.dict")
  echo "== $name: ${seconds}s"
  log="$scratch/$name.log"
  if (cd "$scratch" && "$fuzzer" -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
        "${dict[@]}" -print_final_stats=1 "$scratch/$name" >"$log" 2>&1); then
    grep -E '^stat::(number_of_executed_units|peak_rss_mb)' "$log" || true
  else
    tail -n 60 "$log" >&2
    echo "$name: failed (crash, leak, timeout or out of memory; the reproducer is in the log above)" >&2
    exit 1
  fi
done
[ $found -eq 1 ] || { echo "run-fuzzers: no fuzz_* binaries in $bin" >&2; exit 1; }
