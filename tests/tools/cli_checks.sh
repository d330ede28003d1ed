# SPDX-License-Identifier: MIT
# Sourced by the command-line tests: a scratch directory $tmp (removed on exit), pass and failure
# counts, and the checks. finish prints the plain closing line and fails when anything failed.

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
passes=0

# expect <code> <stderr-substring or ''> <command...>
expect() {
  local code=$1 needle=$2
  shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" -ne "$code" ] || { [ -n "$needle" ] && ! grep -qF -- "$needle" "$tmp/err"; }; then
    echo "FAIL: $* -> exit $got (expected $code), stderr: $(head -c 300 "$tmp/err")"
    failures=$((failures + 1))
  else
    passes=$((passes + 1))
  fi
}

# check <description> <command...>: passes when the command succeeds
check() {
  local what=$1
  shift
  if "$@"; then passes=$((passes + 1)); else echo "FAIL: $what"; failures=$((failures + 1)); fi
}

finish() {
  echo "$passes passed, $failures failed"
  [ "$failures" -eq 0 ]
}
