/* SPDX-License-Identifier: MIT */
#pragma once
// File names in JSON output. A POSIX name is any bytes, JSON text is UTF-8 (nlohmann::json throws
// on anything else when it dumps).
#include <cstdio>
#include <string>
#include <string_view>

namespace tristream {

// `name` with every byte that is not part of a valid UTF-8 sequence (overlong forms and
// surrogates included) written as the four characters \xNN; valid UTF-8 is kept as it is.
inline std::string json_file_name(std::string_view name) {
  std::string out;
  std::size_t i = 0;
  auto byte = [&](std::size_t k) { return static_cast<unsigned char>(name[k]); };
  while (i < name.size()) {
    const unsigned char c = byte(i);
    std::size_t len = 0;
    unsigned lo = 0x80, hi = 0xBF;  // allowed range of the second byte
    if (c < 0x80) len = 1;
    else if (c >= 0xC2 && c <= 0xDF) len = 2;
    else if (c >= 0xE0 && c <= 0xEF) len = 3, lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    else if (c >= 0xF0 && c <= 0xF4) len = 4, lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    bool valid = len > 0 && i + len <= name.size();
    for (std::size_t k = 1; valid && k < len; ++k) {
      const unsigned b = byte(i + k);
      valid = k == 1 ? (b >= lo && b <= hi) : (b >= 0x80 && b <= 0xBF);
    }
    if (valid) {
      out.append(name.substr(i, len));
      i += len;
    } else {
      char esc[5];
      std::snprintf(esc, sizeof esc, "\\x%02X", c);
      out += esc;
      ++i;
    }
  }
  return out;
}

}  // namespace tristream
