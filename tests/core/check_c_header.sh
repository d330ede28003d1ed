#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Compiles a file that includes the public C headers (tristream/tristream.h, version.h) alone and uses its
# names, once per language mode: C89 through C2x and C++98 through C++20, each with
# -Wall -Wextra -pedantic -Werror. Fails naming the first mode that does not compile.
# Usage: check_c_header.sh CC CXX INCLUDE_DIR WORK_DIR
set -euo pipefail
cc=${1:?usage: check_c_header.sh CC CXX INCLUDE_DIR WORK_DIR}
cxx=${2:?}
include=${3:?}
work=${4:?}
mkdir -p "$work"
cat >"$work/use_header.c" <<'SRC'
#include "tristream/tristream.h"
#include "tristream/version.h"

static void sink(void* context, const ts_tile* tile) {
  (void)context;
  (void)tile;
}

int use_header(const void* bytes, size_t size) {
  ts_blob blob;
  ts_params params = TS_PARAMS_INIT;
  static uint8_t tile[16];
  static uint8_t work[64];
  const char* version = TRISTREAM_VERSION;
  ts_status s = ts_open(bytes, size, &blob, (uint32_t*)0);
  (void)version;
  params.format = TS_RGB565_BE;
  params.target_stride = 8;
  params.target = tile;
  if (s == TS_OK) s = ts_render(&blob, &params, tile, sizeof tile, work, sizeof work, sink, (void*)0);
  return s == TS_BAD_PARAMS || s == TS_NOT_COMPILED || params.format == TS_FORMAT_UNSET ? 1 : (int)s;
}
SRC
cp "$work/use_header.c" "$work/use_header.cpp"
status=0
for std in c89 c99 c11 c17 c2x; do
  if ! "$cc" -std=$std -Wall -Wextra -pedantic -Werror -I"$include" -c "$work/use_header.c" -o "$work/use_header.$std.o"; then
    echo "check_c_header: tristream.h does not compile as -std=$std" >&2
    status=1
  fi
done
for std in c++98 c++11 c++14 c++17 c++20; do
  if ! "$cxx" -std=$std -Wall -Wextra -pedantic -Werror -I"$include" -c "$work/use_header.cpp" -o "$work/use_header.$std.o"; then
    echo "check_c_header: tristream.h does not compile as -std=$std" >&2
    status=1
  fi
done
[ $status -eq 0 ] && echo "tristream.h compiles as C89, C99, C11, C17, C2x, C++98, C++11, C++14, C++17 and C++20"
exit $status
