/* SPDX-License-Identifier: MIT */
#pragma once
// The host packer: a Triangulation to the core's blob format (firmware_core/include/tristream/blob.h).
#include <cstdint>
#include <string_view>
#include <vector>

#include "model/triangulation.h"
#include "tristream/blob.h"

namespace tristream {

// "bilinear" or "zienkiewicz"; throws UsageError naming the accepted methods otherwise.
core::Method parse_core_method(std::string_view name);
std::string_view to_string(core::Method method);

// Packs `tri` for `method`: positions rounded to the nearest 1 / 2^TS_SUBPIXEL_BITS pixel,
// values to q8_8, zienkiewicz gradients (reference/gradients.h, the reference's estimate) to
// q19_12; boundary edges flagged inclusive and every boundary vertex given exactly one owner
// triangle; triangles sorted by top row. Throws DataError ("<name>: triangle N: ...") when the
// triangulation exceeds the core's limits, a triangle collapses when rounded, or two vertices that
// triangles use round to one position ("<name>: vertices on lines A (x, y) and B (x, y) both round
// to ...", indices for a mesh not read from a file).
// `gradients`, when given (zienkiewicz only), replaces the estimate: per layer, per vertex and
// value gx, gy in q19_12, the layout of the blob's section (unpack_blob returns it, so that a blob
// read back packs to the same bytes); a count that does not match the mesh throws DataError.
using BlobGradients = std::vector<std::vector<std::int32_t>>;
std::vector<std::uint8_t> pack_blob(const Triangulation& tri, core::Method method, std::string_view name = "input",
                                    const BlobGradients* gradients = nullptr);

}  // namespace tristream
