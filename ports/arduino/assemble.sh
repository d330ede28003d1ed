#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Assembles the Arduino library from the repository: OUT/tristream/ in the layout the Arduino
# builder expects (library.properties, and one src/ folder that it compiles recursively and puts on
# the include path: the core's public headers under src/tristream/, its sources and private headers
# in src/core/, so that only tristream.h sits at the top of src/, where the builder looks for the
# headers a library provides), the example sketch with the demo picture packed by tripack, and the folder zipped
# as OUT/tristream-VERSION.zip (Sketch > Include Library > Add .ZIP Library).
# The files are copied, not kept twice in the repository: firmware_core/ stays the one source.
# Usage: ports/arduino/assemble.sh OUT TRIPACK
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=${1:?usage: assemble.sh OUT TRIPACK}
tripack=${2:?usage: assemble.sh OUT TRIPACK}
version=$(sed -n 's/^#define TRISTREAM_VERSION "\(.*\)"$/\1/p' "$root/firmware_core/include/tristream/version.h")
listed=$(sed -n 's/^version=//p' "$here/library.properties")
if [ "$listed" != "$version" ]; then
  echo "assemble.sh: ports/arduino/library.properties says version=$listed, tristream/version.h $version" >&2
  exit 1
fi
lib="$out/tristream"
rm -rf "$lib" "$out/tristream-$version.zip"
mkdir -p "$lib/src/core" "$lib/examples"
cp "$here/library.properties" "$root/LICENSE" "$lib/"
cp "$here/tristream.h" "$lib/src/"
cp -R "$root/firmware_core/include/tristream" "$lib/src/tristream"
cp "$root"/firmware_core/src/*.cpp "$root"/firmware_core/src/*.h "$lib/src/core/"
# The platform forms of the kernels (firmware_core/src/backend.h), in their folders.
for d in "$root"/firmware_core/src/*/; do cp -R "$d" "$lib/src/core/"; done
cp -R "$here/examples/." "$lib/examples/"
sketch="$lib/examples/TristreamBands"
"$tripack" "$root/data/demo/kodim23.rgb.tri" -o "$sketch/photo.c" --symbol photo --width 320 --height 240 \
  --tile-width 0 --tile-height 16 >/dev/null
(cd "$out" && cmake -E tar cf "tristream-$version.zip" --format=zip tristream)
echo "$lib"
