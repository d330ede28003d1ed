/* SPDX-License-Identifier: MIT */
#pragma once
// Host-side error types. Tools map each to a distinct exit code (sysexits.h values).
#include <stdexcept>
#include <string>

namespace tristream {

// Command line misuse. Exit code 64.
struct UsageError : std::runtime_error { using std::runtime_error::runtime_error; };
// Input that is present but malformed ("file:line: expected ..., found ..."). Exit code 65.
struct DataError : std::runtime_error { using std::runtime_error::runtime_error; };
// Input that is missing or unreadable. Exit code 66.
struct InputError : std::runtime_error { using std::runtime_error::runtime_error; };
// Output that cannot be written. Exit code 73.
struct OutputError : std::runtime_error { using std::runtime_error::runtime_error; };

enum ExitCode : int {
  exit_ok = 0,
  exit_check_failed = 1,  // a check the command was asked to make failed (thresholds, golden images)
  exit_usage = 64,
  exit_data = 65,
  exit_noinput = 66,
  exit_software = 70,
  exit_oserr = 71,  // out of memory
  exit_cantcreate = 73,
  exit_ioerr = 74,  // results could not be written to stdout
};

}  // namespace tristream
