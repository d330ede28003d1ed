#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The cortex-m4 preset (CMakePresets.json) as a firmware project uses it: configured with a
# configuration (RGB565 big-endian, zienkiewicz, RGB, one mesh), built, installed alone into a
# prefix, then checked:
#   - a CMAKE_CXX_FLAGS given on the command line, which replaces the toolchain's CPU flags, stops
#     the configure (it had built an ARMv4T core that linked without a warning and faulted), and
#     so does a TS_ knob in it (the install would not record it)
#   - the install has no tools, and every object of libtristream.a is Armv7E-M, hard-float ABI
#   - the package records the configuration: tristream/config_build.h, tristreamConfig.cmake, tristream.pc
#   - a firmware (tests/package/firmware, find_package with the preset's toolchain file) with a v1
#     and a compressed blob links for the hard-float ABI
#   - at compile time the generated blob headers refuse a format or method the installed core
#     leaves out, and config_build.h a file compiled for another CPU, float ABI or knob value.
# Usage: check_preset.sh SOURCE_DIR WORK TRIPACK [LAUNCHER]
set -uo pipefail
src=$1
work=$2
tripack=$3
launcher=${4:-}
failures=0
passes=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { passes=$((passes + 1)); }
rm -rf "$work"
mkdir -p "$work"
launch=()
[ -n "$launcher" ] && launch=(-DCMAKE_C_COMPILER_LAUNCHER="$launcher" -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
flags=(-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16)
cd "$src" || exit 1

# The flags CMAKE_CXX_FLAGS would have replaced.
if cmake --preset cortex-m4 -B "$work/replaced" -DCMAKE_CXX_FLAGS=-DTS_PIXEL_FORMATS=0x08 >"$work/replaced.log" 2>&1; then
  fail "configure with -DCMAKE_CXX_FLAGS=-DTS_PIXEL_FORMATS=0x08 succeeded"
elif ! tr -s ' \n' '  ' <"$work/replaced.log" | grep -qF "lacks -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16"; then
  fail "configure with a replacing CMAKE_CXX_FLAGS: $(tail -c 600 "$work/replaced.log")"
else pass; fi

# A knob in CMAKE_CXX_FLAGS (with the CPU flags) would build a core the install does not describe.
if cmake --preset cortex-m4 -B "$work/knob" -DCMAKE_CXX_FLAGS="${flags[*]} -DTS_PIXEL_FORMATS=0x08" >"$work/knob.log" 2>&1; then
  fail "configure with -DTS_PIXEL_FORMATS=0x08 in CMAKE_CXX_FLAGS succeeded"
elif ! tr -s ' \n' '  ' <"$work/knob.log" | grep -qF "defines TS_PIXEL_FORMATS: set the cache variable TRISTREAM_PIXEL_FORMATS"; then
  fail "configure with a knob in CMAKE_CXX_FLAGS: $(tail -c 600 "$work/knob.log")"
else pass; fi

# Configure, build, install (no --component): the preset's own commands, with a build directory
# of the test's and the configuration's cache variables.
if ! cmake --preset cortex-m4 -B "$work/build" -DTRISTREAM_PIXEL_FORMATS=0x08 -DTRISTREAM_METHODS=0x2 \
     -DTRISTREAM_COLOR_SPACES=0x2 -DTRISTREAM_LAYERED=0 "${launch[@]}" >"$work/build.log" 2>&1 ||
   ! cmake --build "$work/build" -j2 >>"$work/build.log" 2>&1 ||
   ! cmake --install "$work/build" --prefix "$work/prefix" >>"$work/build.log" 2>&1; then
  echo "FAIL: the cortex-m4 preset does not configure, build or install: $(tail -c 1500 "$work/build.log")"
  exit 1
fi
prefix=$work/prefix
[ -e "$prefix/bin" ] && fail "the core-only install has $prefix/bin: $(ls "$prefix/bin")" || pass
attributes=$(arm-none-eabi-readelf -A "$prefix/lib/libtristream.a")
objects=$(grep -c '^File:' <<<"$attributes")
arch=$(grep -c 'Tag_CPU_arch: v7E-M$' <<<"$attributes")
vfp=$(grep -c 'Tag_ABI_VFP_args: VFP registers$' <<<"$attributes")
if [ "$objects" -lt 6 ] || [ "$arch" -ne "$objects" ] || [ "$vfp" -ne "$objects" ]; then
  fail "libtristream.a: $objects objects, $arch Armv7E-M, $vfp with VFP register arguments"
else pass; fi
for want in '#define TS_PIXEL_FORMATS 0x08' '#define TS_METHODS 0x2' '#define TS_COLOR_SPACES 0x2' '#define TS_LAYERED 0' \
            '#define TS_SUBPIXEL_BITS 4' '#if !defined(__ARM_PCS_VFP)'; do
  grep -qxF "$want" "$prefix/include/tristream/config_build.h" && pass || fail "config_build.h lacks '$want'"
done
grep -qx '#define TRISTREAM_INSTALLED_CONFIG 1' "$prefix/include/tristream/config.h" && pass || fail "installed config.h does not include config_build.h"
for want in 'set(tristream_PIXEL_FORMATS 0x08)' 'set(tristream_FLOAT_ABI "hard")' \
            'set(tristream_ARM_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")'; do
  grep -qF "$want" "$prefix/lib/cmake/tristream/tristreamConfig.cmake" && pass || fail "tristreamConfig.cmake lacks '$want'"
done
[ "$(PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --variable=float_abi tristream)" = hard ] && pass || fail "tristream.pc: float_abi is not hard"

# Blobs for the firmware and for the refusals.
blobs=$work/blobs
mkdir -p "$blobs"
tri=$src/tests/golden/rgb.tri
"$tripack" "$tri" -o "$blobs/ok.c" -m zienkiewicz -f rgb565be --tile 16 >/dev/null &&
  "$tripack" "$tri" -o "$blobs/okc.c" -m zienkiewicz -f rgb565be --tile 16 --compress >/dev/null &&
  "$tripack" "$tri" -o "$blobs/le.c" -m zienkiewicz -f rgb565le >/dev/null &&
  "$tripack" "$tri" -o "$blobs/bil.c" -m bilinear -f rgb565be >/dev/null || { fail "tripack"; exit 1; }

# The firmware, through the CMake package and the preset's toolchain file; linked for hard float.
if cmake -S "$src/tests/package/firmware" -B "$work/firmware" -DCMAKE_TOOLCHAIN_FILE="$src/cmake/toolchains/cortex-m4.cmake" \
     -DCMAKE_BUILD_TYPE=MinSizeRel -DCMAKE_PREFIX_PATH="$prefix" -DBLOB_DIR="$blobs" "${launch[@]}" \
     -DEXPECTED_PIXEL_FORMATS=0x08 -DEXPECTED_METHODS=0x2 -DEXPECTED_FLOAT_ABI=hard -DEXPECTED_ARM_FLAGS="${flags[*]}" \
     >"$work/firmware.log" 2>&1 && cmake --build "$work/firmware" >>"$work/firmware.log" 2>&1; then
  if arm-none-eabi-readelf -A "$work/firmware/firmware.elf" | grep -q 'Tag_ABI_VFP_args: VFP registers'; then pass
  else fail "firmware.elf is not hard-float"; fi
else
  fail "the hard-float firmware does not configure, compile or link: $(tail -c 1500 "$work/firmware.log")"
fi

# Compile-time refusals: <expected message> <file> [compiler flags...] (the CPU's flags unless given).
refused() {
  local needle=$1 file=$2
  shift 2
  local args=("$@")
  [ ${#args[@]} -eq 0 ] && args=("${flags[@]}")
  if arm-none-eabi-gcc "${args[@]}" -std=c89 -Wall -Wextra -pedantic -Werror -I"$prefix/include" -I"$blobs" \
       -c "$file" -o "$work/refused.o" 2>"$work/refused.err"; then
    fail "$(basename "$file") with ${args[*]} compiled (expected: $needle)"
  elif ! grep -qF "$needle" "$work/refused.err"; then
    fail "$(basename "$file") with ${args[*]}: expected '$needle', got: $(head -c 400 "$work/refused.err")"
  else pass; fi
}
echo '#include "le.h"' >"$work/use_le.c"
echo '#include "bil.h"' >"$work/use_bil.c"
echo '#include "ok.h"' >"$work/use_ok.c"
refused "the descriptor is for rgb565le, which this core leaves out (TS_PIXEL_FORMATS)" "$work/use_le.c"
refused "the blob is bilinear, which this core leaves out (TS_METHODS)" "$work/use_bil.c"
refused "the descriptor is for rgb565le, which this core leaves out (TS_PIXEL_FORMATS)" "$blobs/le.c"
refused "built for the hard-float calling convention" "$work/use_ok.c" -mcpu=cortex-m4 -mthumb -mfloat-abi=soft
refused "built for Armv7E-M" "$work/use_ok.c" -Os  # no -mcpu: arm-none-eabi-gcc's default, ARMv4T
refused "built for Armv7E-M" "$work/use_ok.c" -mcpu=cortex-m0plus -mthumb
refused "built for a CPU with the DSP extension" "$work/use_ok.c" -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
refused "TS_PIXEL_FORMATS: this tristream core was built with 0x08" "$work/use_ok.c" "${flags[@]}" -DTS_PIXEL_FORMATS=0x1F
# And the same file with the core's CPU and knobs compiles.
if arm-none-eabi-gcc "${flags[@]}" -std=c89 -Wall -Wextra -pedantic -Werror -DTS_PIXEL_FORMATS=0x08 -I"$prefix/include" \
     -I"$blobs" -c "$work/use_ok.c" -o "$work/ok.o" 2>"$work/ok.err"; then pass
else fail "use_ok.c with the core's CPU: $(head -c 400 "$work/ok.err")"; fi

echo "check_preset: $passes passed, $failures failed"
[ $failures -eq 0 ]
