#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Cross-compiles firmware_core for Cortex-M4 (arm-none-eabi-g++ -Os -fno-exceptions -fno-rtti),
# links a firmware-shaped demo, prints text/data/bss, and fails if any heap allocator of the C
# or C++ runtime was linked (the C allocation functions, reentrant or not, and the C++
# allocation operators, mangled _Znwj/_Znaj/_ZdlPv/_ZdaPv); then every preset of CMakePresets.json
# but cortex-m4 (ctest's package_preset_cortex_m4 checks that one) configured, built and
# installed alone, with each object's architecture and float ABI checked. Usage: build.sh [build-dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build-cross}
cmake -S "$root/firmware_core/cross" -B "$build/firmware" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/arm-none-eabi.cmake" \
  -DTRISTREAM_CROSS=firmware -DCMAKE_BUILD_TYPE=MinSizeRel >/dev/null
cmake --build "$build/firmware" -j2
echo "== firmware_core for Cortex-M4 (-Os), library and demo image (the image includes the demo blob):"
arm-none-eabi-size -t "$build/firmware/ts_core/libts_core.a" | tail -1 |
  awk '{print "libts_core.a (all formats and methods): text " $1 " data " $2 " bss " $3}'
arm-none-eabi-size -t "$build/firmware/libts_core_minimal.a" | tail -1 |
  awk '{print "libts_core_minimal.a (TS_PIXEL_FORMATS=0x08 TS_METHODS=0x2: RGB565 BE, zienkiewicz): text " $1 " data " $2 " bss " $3}'
for elf in "$build/firmware/firmware_demo.elf" "$build/firmware/firmware_demo_minimal.elf"; do
  arm-none-eabi-size "$elf"
  forbidden=$(arm-none-eabi-nm "$elf" | awk '{print $NF}' |
    grep -E '^_?(m|c|re)alloc(_r)?$|^_?free(_r)?$|^_Zn[wa]j|^_Zd[la]Pv' || true)
  if [ -n "$forbidden" ]; then
    echo "error: $elf links an allocator: $forbidden" >&2
    exit 1
  fi
done
echo "no heap allocator linked"
# The core compiled as a firmware's Debug build (-O0) and by clang for Cortex-M4 (as armclang's
# users would): the inline assembly must leave the compiler registers enough in both (compile only).
echo "== firmware_core at -O0 (arm-none-eabi-g++) and -O2 (clang for thumbv7em, when installed):"
flags=(-std=c++17 -mcpu=cortex-m4 -mthumb -Wall -Wextra -Werror -fno-exceptions -fno-rtti -I"$root/firmware_core/include")
clang=$(command -v clang++-14 || true)
for src in "$root"/firmware_core/src/*.cpp; do
  arm-none-eabi-g++ "${flags[@]}" -O0 -c "$src" -o /dev/null
  if [ -n "$clang" ]; then
    "$clang" --target=thumbv7em-none-eabi -isystem /usr/lib/arm-none-eabi/include "${flags[@]}" -O2 -c "$src" -o /dev/null
  fi
done
echo "compiled${clang:+ (and with $clang)}"
# The presets: the core alone for each CPU, installed without --component; readelf -A must show
# the preset's architecture and calling convention in every object of the installed library.
echo "== the presets (CMakePresets.json), each built and installed alone:"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
check_preset() {  # preset, Tag_CPU_arch, Tag_ABI_VFP_args ("" for the base standard)
  local preset=$1 arch=$2 vfp=$3 dir=$build/preset-$1
  (cd "$root" && cmake --preset "$preset" -B "$dir/build" "${launcher[@]}" >/dev/null)
  cmake --build "$dir/build" -j2 >/dev/null
  rm -rf "$dir/prefix"
  cmake --install "$dir/build" --prefix "$dir/prefix" >/dev/null
  local attrs objects
  attrs=$(arm-none-eabi-readelf -A "$dir/prefix/lib/libtristream.a")
  objects=$(grep -c '^File:' <<<"$attrs")
  if [ "$(grep -c "Tag_CPU_arch: $arch\$" <<<"$attrs")" -ne "$objects" ]; then
    echo "error: $preset: not every object is $arch" >&2; exit 1
  fi
  if [ -n "$vfp" ] && [ "$(grep -c "Tag_ABI_VFP_args: $vfp\$" <<<"$attrs")" -ne "$objects" ]; then
    echo "error: $preset: not every object has Tag_ABI_VFP_args: $vfp" >&2; exit 1
  fi
  if [ -z "$vfp" ] && grep -q 'Tag_ABI_VFP_args' <<<"$attrs"; then
    echo "error: $preset: objects pass arguments in VFP registers" >&2; exit 1
  fi
  arm-none-eabi-size -t "$dir/prefix/lib/libtristream.a" | tail -1 |
    awk -v p="$preset" -v a="$arch" -v v="${vfp:-base (soft)}" '{printf "%-17s %-7s %-15s text %s data %s bss %s\n", p, a, v, $1, $2, $3}'
}
check_preset cortex-m4-softfp v7E-M ""
check_preset cortex-m0plus v6S-M ""
check_preset cortex-m7 v7E-M "VFP registers"
check_preset cortex-m33 v8-M.mainline "VFP registers"
