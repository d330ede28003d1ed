#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The ways a firmware project takes the core, each built and run on a blob:
#   install PREFIX                 cmake --install the core component of BUILD_DIR into PREFIX
#   find-package PREFIX WORK       consumer/ configured with find_package(tristream CONFIG) from PREFIX
#   pkg-config PREFIX WORK         consumer/consumer.c compiled by CC with pkg-config tristream from PREFIX
#   add-subdirectory SOURCE WORK   consumer/ with add_subdirectory(SOURCE/firmware_core) alone
# Consumers build as Debug (-O0): the test is of the build set-up, and -O0 compiles fastest.
# Environment: BUILD_DIR, CC, CXX, VERSION (expected), BLOB (a blob file), FLAGS (extra compiler
# and linker flags, e.g. the sanitizers of the build under test), LAUNCHER (optional compiler launcher).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mode=${1:?usage: check_package.sh install|find-package|pkg-config|add-subdirectory DIR [WORK]}
dir=${2:?}
work=${3:-}
configure() {
  rm -rf "$work"
  cmake -S "$here/consumer" -B "$work" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" \
    -DCMAKE_C_FLAGS="${FLAGS:-}" -DCMAKE_CXX_FLAGS="${FLAGS:-}" -DCMAKE_EXE_LINKER_FLAGS="${FLAGS:-}" \
    ${LAUNCHER:+-DCMAKE_C_COMPILER_LAUNCHER="$LAUNCHER" -DCMAKE_CXX_COMPILER_LAUNCHER="$LAUNCHER"} "$@" >"$work.log" ||
    { cat "$work.log"; exit 1; }
  cmake --build "$work" -j2 >>"$work.log" || { cat "$work.log"; exit 1; }
}
case "$mode" in
  install)
    rm -rf "$dir"
    cmake --install "$BUILD_DIR" --prefix "$dir" --component core
    for f in include/tristream/tristream.h include/tristream/version.h lib/libtristream.a \
             lib/cmake/tristream/tristreamConfig.cmake lib/cmake/tristream/tristreamConfigVersion.cmake \
             lib/pkgconfig/tristream.pc; do
      [ -f "$dir/$f" ] || { echo "check_package: $dir/$f was not installed" >&2; exit 1; }
    done ;;
  find-package)
    configure -DCMAKE_PREFIX_PATH="$dir" -DTRISTREAM_EXPECTED_VERSION="$VERSION"
    "$work/consumer" "$BLOB" ;;
  add-subdirectory)
    configure -DTRISTREAM_FIRMWARE_CORE="$dir/firmware_core"
    "$work/consumer" "$BLOB" ;;
  pkg-config)
    export PKG_CONFIG_PATH="$dir/lib/pkgconfig"
    got=$(pkg-config --modversion tristream)
    [ "$got" = "$VERSION" ] || { echo "check_package: tristream.pc says version $got, expected $VERSION" >&2; exit 1; }
    mkdir -p "$work"
    # The core is C++ but needs nothing from the C++ runtime: the C driver links it.
    "$CC" -std=c99 -Wall -Wextra -Wpedantic -Werror ${FLAGS:-} $(pkg-config --cflags tristream) \
      "$here/consumer/consumer.c" $(pkg-config --libs tristream) -o "$work/consumer"
    "$work/consumer" "$BLOB" ;;
  *) echo "check_package: unknown mode $mode" >&2; exit 64 ;;
esac
