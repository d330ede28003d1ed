#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian packages a task needs, and only those that are missing.
# Usage: tools/install-deps.sh [build|checks|fuzz|cross|bench|mcu|experiments|ecosystems|python|browser|all]...   (default: build)
# checks: universal-ctags, for the function-length check of make test (tests/tools/check_function_lengths.py).
# python: pybind11 and Python's headers for the Python module (python/), numpy for it and its tests.
# browser: headless Chromium, for the check of the report page (make experiments-quick).
# mcu: the Arm (Cortex-M4, Cortex-M0+) and RISC-V rv32imc cross compilers, unicorn and capstone (make bench-mcu,
#   bench_mcu tests).
# ecosystems: the Cortex-M4 compiler, arduino-builder and PyYAML of tests/ecosystems (make test).
set -euo pipefail

declare -A groups=(
  [build]="cmake make g++ pkg-config catch2 libstb-dev libpng-dev libjpeg62-turbo-dev libcli11-dev nlohmann-json3-dev libbenchmark-dev"
  [checks]="universal-ctags python3"
  [fuzz]="clang-14 libclang-rt-14-dev"
  [cross]="gcc-arm-none-eabi libstdc++-arm-none-eabi-newlib libnewlib-arm-none-eabi binutils-arm-none-eabi qemu-user file"
  [bench]="valgrind"
  [mcu]="gcc-arm-none-eabi libstdc++-arm-none-eabi-newlib libnewlib-arm-none-eabi binutils-arm-none-eabi libunicorn-dev libcapstone-dev pkg-config gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf"
  [experiments]="python3 python3-numpy python3-scipy python3-matplotlib python3-pil python3-tqdm"
  [ecosystems]="gcc-arm-none-eabi libstdc++-arm-none-eabi-newlib libnewlib-arm-none-eabi python3 python3-yaml arduino-builder"
  [python]="python3 python3-dev python3-numpy pybind11-dev python3-pybind11"
  [browser]="chromium"
)

wanted=()
for group in "${@:-build}"; do
  if [ "$group" = all ]; then
    for g in "${!groups[@]}"; do wanted+=(${groups[$g]}); done
  elif [ -n "${groups[$group]:-}" ]; then
    wanted+=(${groups[$group]})
  else
    echo "install-deps: unknown group '$group' (expected build, checks, fuzz, cross, bench, mcu, experiments, ecosystems, python, browser or all)" >&2
    exit 64
  fi
done

missing=()
for pkg in "${wanted[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$pkg")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 77; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
