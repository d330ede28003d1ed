/* SPDX-License-Identifier: MIT */
#pragma once
// The shared frame of every command-line tool: runs the body, prints diagnostics on stderr
// as "<tool>: <message>" and maps each error type to its exit code (common/errors.h). Gives every
// tool --version (the one version of tristream/version.h). Results that could not be written to
// stdout (a full disk, a closed stdout) are exit 74.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>

#include "common/activity.h"
#include "common/errors.h"
#include "tristream/version.h"

namespace tristream {

// Flushes stdout; false (with a message) when anything written to it was lost.
inline bool stdout_written(const char* tool) {
  const bool ok = std::fflush(stdout) == 0 && !std::ferror(stdout);
  if (!ok) std::fprintf(stderr, "%s: cannot write the results to stdout (%s)\n", tool, std::strerror(errno));
  return ok;
}

template <class Body>
int run_tool(const char* tool, CLI::App& app, int argc, char** argv, Body&& body) {
  try {
    app.set_version_flag("--version", std::string(tool) + " (tristream) " + TRISTREAM_VERSION);
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      std::fprintf(stderr, "%s: %s\nRun '%s --help' for usage.\n", tool, e.what(), tool);
      return exit_usage;
    }
    const int code = body();
    return stdout_written(tool) ? code : int(exit_ioerr);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: %s\n", tool, e.what());
    return exit_usage;
  } catch (const DataError& e) {
    std::fprintf(stderr, "%s: %s\n", tool, e.what());
    return exit_data;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s: %s\n", tool, e.what());
    return exit_noinput;
  } catch (const OutputError& e) {
    std::fprintf(stderr, "%s: %s\n", tool, e.what());
    return exit_cantcreate;
  } catch (const std::bad_alloc&) {
    // No allocation here: the activity's text is already there; fputs does not allocate.
    std::fprintf(stderr, "%s: out of memory", tool);
    const std::string& what = activity_at_failure.empty() ? current_activity : activity_at_failure;
    if (!what.empty()) {
      std::fputs(" while ", stderr);
      std::fputs(what.c_str(), stderr);
    }
    std::fputs(" (README.md gives each tool's memory per vertex and per pixel)\n", stderr);
    return exit_oserr;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", tool, e.what());
    return exit_software;
  }
}

}  // namespace tristream
