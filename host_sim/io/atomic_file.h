#pragma once
// Whole-file writes that never leave a half-written file behind.
#include <string>
#include <string_view>

namespace tristream {

// Writes `bytes` to "<path>.tmp.<pid>" and renames it over `path`. Throws OutputError naming
// the path and the system error.
void write_file_atomically(const std::string& path, std::string_view bytes);

// Reads a whole file. Throws InputError naming the path and the system error.
std::string read_file(const std::string& path);

}  // namespace tristream
