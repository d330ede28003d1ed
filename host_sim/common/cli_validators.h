/* SPDX-License-Identifier: MIT */
#pragma once
// Validators of the tools' numeric options that judge the text as typed and echo it in their
// messages, with the limits in words (CLI11's own print a double's bounds in full, and read
// integers with strtoll in base 0, which clamps past 2^63 and takes "010" as octal).
#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <exception>
#include <string>
#include <system_error>

namespace tristream {

// A validator of a finite number above `lo` (or at least `lo` when `inclusive`) and at most
// `hi`; NaN and infinities are refused. The message states `expected` (not the bounds in full).
inline CLI::Validator finite_in(double lo, bool inclusive, double hi, const std::string& expected) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        const bool ok = used == text.size() && std::isfinite(v) && (inclusive ? v >= lo : v > lo) && v <= hi;
        return ok ? std::string() : "expected " + expected + ", found '" + text + "'";
      },
      expected);
}

// A transform that takes a decimal integer in lo..hi, judged on the text as typed, and hands it
// on without leading zeros: CLI11 reads integers with strtoll in base 0, which clamps a number past
// 2^63 to 2^63 - 1 and reads "010" as octal 8. The message echoes the text and states `expected`.
inline CLI::Validator decimal_in(long long lo, long long hi, const std::string& expected) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const char* first = text.data() + (text.size() > 1 && text[0] == '+');
        long long v = 0;
        const auto [end, error] = std::from_chars(first, text.data() + text.size(), v);
        if (error == std::errc::invalid_argument || end != text.data() + text.size())
          return "expected " + expected + ", found '" + text + "' (not a decimal integer)";
        if (error == std::errc::result_out_of_range || v < lo || v > hi)
          return "expected " + expected + ", found '" + text + "' (out of range)";
        text = std::to_string(v);
        return std::string();
      },
      expected);
}

}  // namespace tristream
