/* SPDX-License-Identifier: MIT */
#pragma once
// The step a host tool is in, named for its diagnostics: run_tool (tool_main.h) reports
// "out of memory while <activity>".
#include <exception>
#include <string>
#include <utility>

namespace tristream {

// What the tool is doing, for the message when memory runs out ("out of memory while <activity>").
// Set it with an Activity around each step that allocates in proportion to its input. The
// activity that an exception leaves is kept in activity_at_failure (the destructors run before
// run_tool's handler does).
inline thread_local std::string current_activity;
inline thread_local std::string activity_at_failure;

class Activity {
 public:
  explicit Activity(std::string what)
      : previous_(std::move(current_activity)), exceptions_(std::uncaught_exceptions()) {
    current_activity = std::move(what);
  }
  ~Activity() {
    if (std::uncaught_exceptions() > exceptions_ && activity_at_failure.empty())
      activity_at_failure.swap(current_activity);
    current_activity = std::move(previous_);
  }
  Activity(const Activity&) = delete;
  Activity& operator=(const Activity&) = delete;

 private:
  std::string previous_;
  int exceptions_;
};

}  // namespace tristream
