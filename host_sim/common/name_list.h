/* SPDX-License-Identifier: MIT */
#pragma once
// The valid names of an option as messages list them: "a, b or c".
#include <iterator>
#include <string>
#include <string_view>

namespace tristream {

// The names of a name table (entries with a `name` member), joined by `separator`, and by `last`
// before the final one: "a, b or c" by default.
template <class Table>
std::string name_list(const Table& table, std::string_view separator = ", ", std::string_view last = " or ") {
  std::string text;
  std::size_t i = 0;
  for (const auto& entry : table) {
    if (i) text += i + 1 == std::size(table) ? last : separator;
    text += entry.name;
    ++i;
  }
  return text;
}

}  // namespace tristream
