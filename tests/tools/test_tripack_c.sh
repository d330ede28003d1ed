#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tripack -o x.c, v1 and --compress: the generated C compiles (C89 and C99, -Wall -Wextra
# -pedantic -Werror) and links with the core for awkward output names (a keyword, a quote, a
# leading digit, the C API's prefix) and with --symbol, and a program renders its descriptor with
# static buffers of the header's <SYMBOL>_TILE_BUFFER_MAX_BYTES and <SYMBOL>_WORKSPACE_MAX_BYTES
# (ts_render, or ts_render_compressed from the streams), at the descriptor's size and at a smaller
# output with a viewport; <SYMBOL>_BYTES is the blob's size (a compile-time check against the
# .bin's); the header refuses, at compile time, a core without the blob's method, colour space or
# layering or the descriptor's format or of another precision; TS_BLOB_SECTION and TS_BLOB_ALIGN
# place the bytes. Usage: test_tripack_c.sh TRIPACK CC INCLUDE_DIR CORE_LIBRARY SOURCE_DIR [LINK_FLAGS]
# (LINK_FLAGS: what the core library was built with that its users must link, e.g. sanitizers)
set -uo pipefail
tripack=$1
cc=$2
include=$3
core=$4
src=$5
link_flags=${6:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
passes=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { passes=$((passes + 1)); }
tri=$src/tests/golden/rgb.tri
cflags=(-Wall -Wextra -pedantic -Werror -I"$include")

cat >"$tmp/main.c" <<'SRC'
#include <stdio.h>
/* The generated header comes in with -include (its name may not be spellable in an #include).
   COMPRESSED: the blob is "TSTC", rendered from its streams by ts_render_compressed. */
static unsigned char tile[SYMBOL_TILE_BUFFER_MAX_BYTES];
static unsigned char work[SYMBOL_WORKSPACE_MAX_BYTES];
static long tiles;
static void sink(void* context, const ts_tile* t) { (void)context; (void)t; ++tiles; }
static int frame_sink(void* context, const ts_tile* t) { sink(context, t); return 1; }
static ts_status render(const ts_params* p) {
#if COMPRESSED
  ts_compressed_blob blob;
  ts_buffers b;
  ts_status s = ts_open_compressed(SYMBOL.bytes, SYMBOL.size, &blob, 0);
  b.tile[0] = tile;
  b.tile[1] = 0;
  b.tile_size = sizeof tile;
  b.workspace = work;
  b.workspace_size = sizeof work;
  if (s == TS_OK) s = ts_render_compressed(&blob, p, &b, frame_sink, 0, 0);
#else
  ts_blob blob;
  ts_status s = ts_open(SYMBOL.bytes, SYMBOL.size, &blob, 0);
  (void)frame_sink;
  if (s == TS_OK) s = ts_render(&blob, p, tile, sizeof tile, work, sizeof work, sink, 0);
#endif
  return s;
}
int main(void) {
  ts_params p = TS_PARAMS_INIT;
  ts_status s;
  if (SYMBOL.size != SYMBOL_BYTES) {
    printf("descriptor size %lu, header %lu\n", (unsigned long)SYMBOL.size, (unsigned long)SYMBOL_BYTES);
    return 1;
  }
  p.output_width = SYMBOL.output_width;
  p.output_height = SYMBOL.output_height;
  p.tile_width = SYMBOL.tile_width;
  p.tile_height = SYMBOL.tile_height;
  p.format = SYMBOL.format;
  s = render(&p);
  if (s == TS_OK && tiles > 0) {
    /* A smaller output, fitted inside, and a viewport of it. */
    p.output_width = (uint16_t)(SYMBOL.output_width / 2 + 1);
    p.output_height = (uint16_t)(SYMBOL.output_height / 3 + 2);
    p.fit = TS_FIT_INSIDE;
    p.viewport.x0 = 1;
    p.viewport.y0 = 2;
    p.viewport.x1 = p.output_width - 1;
    p.viewport.y1 = p.output_height;
    tiles = 0;
    s = render(&p);
  }
  if (s != TS_OK || tiles == 0) printf("%s, %ld tiles\n", ts_status_text(s), tiles);
  return s == TS_OK && tiles > 0 ? 0 : 1;
}
SRC

# builds <output name> <expected symbol> [tripack options...]: generate, compile both files, link,
# run; then <SYMBOL>_BYTES against the size of the .bin of the same options, at compile time.
builds() {
  local name=$1 symbol=$2
  shift 2
  local dir=$tmp/$RANDOM
  mkdir -p "$dir"
  if ! "$tripack" "$tri" -o "$dir/$name" "$@" >"$dir/log" 2>&1; then fail "tripack -o '$name' $*: $(cat "$dir/log")"; return; fi
  local header=${name%.c}.h macro compressed=0
  macro=$(echo "$symbol" | tr a-z A-Z)
  case " $* " in *" --compress "*) compressed=1 ;; esac
  for std in c89 c99; do
    if ! "$cc" -std=$std "${cflags[@]}" -c "$dir/$name" -o "$dir/blob.$std.o" 2>"$dir/err"; then
      fail "-o '$name' $*: the generated C does not compile as $std: $(head -c 400 "$dir/err")"; return
    fi
    if ! "$cc" -std=$std "${cflags[@]}" -DSYMBOL="$symbol" -DSYMBOL_TILE_BUFFER_MAX_BYTES="${macro}_TILE_BUFFER_MAX_BYTES" \
         -DSYMBOL_WORKSPACE_MAX_BYTES="${macro}_WORKSPACE_MAX_BYTES" -DSYMBOL_BYTES="${macro}_BYTES" \
         -DCOMPRESSED=$compressed -include "$dir/$header" -c "$tmp/main.c" -o "$dir/main.$std.o" 2>"$dir/err"; then
      fail "-o '$name' $*: a user of the header ($symbol) does not compile as $std: $(head -c 400 "$dir/err")"; return
    fi
  done
  if ! "$cc" $link_flags "$dir/main.c99.o" "$dir/blob.c99.o" "$core" -o "$dir/run" 2>"$dir/err" || ! "$dir/run" >"$dir/out"; then
    fail "-o '$name' $*: does not link or render: $(cat "$dir/err" "$dir/out" | head -c 400)"; return
  fi
  # <SYMBOL>_BYTES is the size of the blob tripack writes as .bin with the same options.
  if ! "$tripack" "$tri" -o "$dir/same.bin" "$@" >/dev/null 2>&1; then fail "tripack -o same.bin $*"; return; fi
  local size
  size=$(wc -c <"$dir/same.bin")
  for n in "$size" $((size + 1)); do
    printf 'typedef char size_is_the_blobs[%s_BYTES == %su ? 1 : -1];\n' "$macro" "$n" >"$dir/size.c"
    if "$cc" -std=c89 "${cflags[@]}" -include "$dir/$header" -c "$dir/size.c" -o "$dir/size.o" 2>"$dir/err"; then
      [ "$n" = "$size" ] || { fail "-o '$name' $*: ${macro}_BYTES equals $n, the .bin has $size bytes"; return; }
    else
      [ "$n" != "$size" ] || { fail "-o '$name' $*: ${macro}_BYTES is not the .bin's $size bytes: $(head -c 300 "$dir/err")"; return; }
    fi
  done
  pass
}
builds demo.c demo
builds int.c blob_int
builds 'a"b.c' a_b
builds '7 seas.c' blob_7_seas
builds ts_render.c blob_ts_render
builds main.c blob_main
builds 'x__y.c' x_y
builds int.c my_blob --symbol my_blob
builds bands.c bands --tile-width 0 --tile-height 16 -f rgb888 --width 100 --height 60
builds demo.c demo --compress
builds int.c blob_int --compress -m zienkiewicz
builds int.c my_blob --symbol my_blob --compress -f xrgb8888 --tile 8
builds bands.c bands --tile-width 0 --tile-height 16 -f rgb888 --width 100 --height 60 --compress
tri=$src/tests/golden/ycbcr-layers.tri
builds layers.c layers --compress -m zienkiewicz -f rgb565le --width 90 --height 70 --tile 12
builds layers.c layers -f l8 --tile-width 20 --tile-height 0
# Names of the standard headers' types and macros, and C++'s std: prefixed, so the C compiles.
for name in NULL SIZE_MAX INT8_C std; do
  builds "$name.c" "blob_$name"
done
for name in uint8_t size_t int32_t; do
  builds "$name.c" "${name}_blob"
done
builds uint8_t.c uint8_t_blob --compress

# photo.h and Photo.h are two headers: included together, the second stops with a message (its
# macros would clash), not skipped by a shared include guard.
for form in "" --compress; do
  mkdir -p "$tmp/case$form"
  "$tripack" "$tri" -o "$tmp/case$form/photo.c" $form >/dev/null && "$tripack" "$tri" -o "$tmp/case$form/Photo.c" $form >/dev/null ||
    fail "tripack photo.c / Photo.c $form"
  printf '#include "photo.h"\n#include "Photo.h"\nint main(void) { return 0; }\n' >"$tmp/case$form/both.c"
  if "$cc" -std=c99 "${cflags[@]}" -c "$tmp/case$form/both.c" -o "$tmp/case$form/both.o" 2>"$tmp/err"; then
    fail "photo.h and Photo.h $form compiled together (one skipped or the macros clash silently)"
  elif ! grep -q "PHOTO_BYTES is defined already" "$tmp/err"; then
    fail "photo.h and Photo.h $form: expected 'PHOTO_BYTES is defined already', got: $(head -c 300 "$tmp/err")"
  else pass; fi
  printf '#include "Photo.h"\nint main(void) { return Photo.size == 0; }\n' >"$tmp/case$form/one.c"
  if "$cc" -std=c99 "${cflags[@]}" -c "$tmp/case$form/one.c" -o "$tmp/case$form/one.o" 2>"$tmp/err"; then pass
  else fail "Photo.h $form alone does not compile: $(head -c 300 "$tmp/err")"; fi
done
tri=$src/tests/golden/rgb.tri

# --symbol that cannot be a C name: usage error (64) naming the option.
for bad in int 7x a-b __x _X ts_open main uint8_t size_t NULL SIZE_MAX INT8_C std my_t; do
  "$tripack" "$tri" -o "$tmp/bad.c" --symbol "$bad" >/dev/null 2>"$tmp/err"
  code=$?
  if [ $code -ne 64 ] || ! grep -q -- "--symbol" "$tmp/err"; then fail "--symbol '$bad' -> exit $code: $(cat "$tmp/err")"; else pass; fi
done

# The guard, of the v1 and of the compressed form: each mismatch stops the compilation with its
# own message; the matching core compiles.
for form in "" --compress; do
"$tripack" "$tri" -o "$tmp/z.c" -m zienkiewicz -f rgb565be $form >/dev/null || fail "tripack zienkiewicz $form"
refuses() {
  local needle=$1
  shift
  if "$cc" -std=c99 "${cflags[@]}" "$@" -c "$tmp/z.c" -o "$tmp/z.o" 2>"$tmp/err"; then fail "$form: compiled with $* (expected: $needle)"
  elif ! grep -qF "$needle" "$tmp/err"; then fail "$form: $*: expected '$needle', got: $(head -c 300 "$tmp/err")"
  else pass; fi
  echo '#include "z.h"' >"$tmp/use_z.c"
  if "$cc" -std=c99 "${cflags[@]}" "$@" -c "$tmp/use_z.c" -o "$tmp/use_z.o" 2>"$tmp/err"; then fail "$form: z.h compiled with $*"
  elif ! grep -qF "$needle" "$tmp/err"; then fail "$form: z.h with $*: expected '$needle', got: $(head -c 300 "$tmp/err")"
  else pass; fi
}
refuses "the blob is zienkiewicz, which this core leaves out (TS_METHODS)" -DTS_METHODS=1
refuses "the descriptor is for rgb565be, which this core leaves out (TS_PIXEL_FORMATS)" -DTS_PIXEL_FORMATS=0x04
refuses "another tristream core configuration" -DTS_SUBPIXEL_BITS=3
refuses "the blob is RGB, which this core leaves out (TS_COLOR_SPACES)" -DTS_COLOR_SPACES=0x5
"$tripack" "$src/tests/golden/ycbcr-layers.tri" -o "$tmp/z.c" -m zienkiewicz -f rgb565be $form >/dev/null || fail "tripack layers $form"
refuses "the blob has a mesh per channel, which this core leaves out (TS_LAYERED)" -DTS_LAYERED=0
refuses "the blob is YCbCr, which this core leaves out (TS_COLOR_SPACES)" -DTS_COLOR_SPACES=0x3
if "$cc" -std=c99 "${cflags[@]}" -DTS_METHODS=2 -DTS_PIXEL_FORMATS=0x08 -DTS_COLOR_SPACES=0x4 -c "$tmp/z.c" -o "$tmp/z.o" 2>"$tmp/err"; then pass
else fail "$form: the layered z.c does not compile against a core with exactly its method, format and colour space: $(cat "$tmp/err")"; fi
"$tripack" "$tri" -o "$tmp/z.c" -m zienkiewicz -f rgb565be $form >/dev/null || fail "tripack zienkiewicz $form"
if "$cc" -std=c99 "${cflags[@]}" -DTS_METHODS=2 -DTS_PIXEL_FORMATS=0x08 -DTS_COLOR_SPACES=0x2 -DTS_LAYERED=0 -c "$tmp/z.c" -o "$tmp/z.o" 2>"$tmp/err"; then pass
else fail "$form: z.c does not compile against a core with exactly its method, format and colour space: $(cat "$tmp/err")"; fi
done

# Placement: the bytes in the named section with the asked alignment (objdump: 2**6 = 64).
if "$cc" -std=c99 "${cflags[@]}" -DTS_BLOB_SECTION='".tsblob"' -DTS_BLOB_ALIGN=64 -c "$tmp/z.c" -o "$tmp/placed.o" 2>"$tmp/err"; then
  objdump -t "$tmp/placed.o" | grep -q '\.tsblob.*z_bytes' || fail "z_bytes is not in section .tsblob: $(objdump -t "$tmp/placed.o" | grep z_bytes)"
  objdump -h "$tmp/placed.o" | grep -A0 '\.tsblob' | grep -q '2\*\*6' || fail ".tsblob is not 64-byte aligned: $(objdump -h "$tmp/placed.o" | grep tsblob)"
  pass
else
  fail "z.c with TS_BLOB_SECTION and TS_BLOB_ALIGN: $(cat "$tmp/err")"
fi

echo "test_tripack_c: $passes passed, $failures failed"
[ $failures -eq 0 ]
