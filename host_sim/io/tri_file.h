/* SPDX-License-Identifier: MIT */
#pragma once
// Reader and writer of .tri triangulation files (docs/FORMAT.md).
#include <string>
#include <string_view>

#include "model/triangulation.h"

namespace tristream {

// Parses .tri text. `source_name` prefixes error messages. Validates everything; computes
// the Delaunay triangulation of a mesh with `triangles 0` or no triangles section; normalizes
// winding (Mesh::normalize_winding). Throws DataError("name:line: expected ..., found ...").
Triangulation parse_tri(std::string_view text, const std::string& source_name);

// Reads and parses a file. Throws InputError when it cannot be read, DataError when malformed.
Triangulation read_tri_file(const std::string& path);

// Formats a triangulation; parse_tri(format_tri(t)) == t (values and positions round-trip
// exactly: shortest representation that reads back to the same double).
std::string format_tri(const Triangulation& tri);

// Writes format_tri(tri) to a temporary file beside `path`, then renames. Throws OutputError.
void write_tri_file(const std::string& path, const Triangulation& tri);

}  // namespace tristream
