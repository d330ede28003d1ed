/* SPDX-License-Identifier: MIT */
#pragma once
// The names of the ways a picture meets an output of another shape (fit.h), one table
// (fit_names.cpp) that every --fit option, manifest and printer uses: "stretch", "inside", "fill".
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "reference/fit.h"

namespace tristream {

struct FitName {
  std::string_view name;
  Fit fit;
};

// In the order of docs/CONVENTIONS.md and the core's Fit.
std::span<const FitName> fit_names();
// The names alone, in that order (for CLI11's IsMember and a manifest's one-of check).
std::vector<std::string> fit_name_list();
std::string_view fit_name(Fit fit);
// The fit of a name; nullopt for any other text.
std::optional<Fit> find_fit(std::string_view name);
// The fit of a name; throws UsageError "fit must be stretch, inside or fill, not "x"" otherwise.
Fit parse_fit(std::string_view name);

}  // namespace tristream
