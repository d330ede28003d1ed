// SPDX-License-Identifier: MIT
#include "reference/fit_names.h"

#include <array>

#include "common/errors.h"
#include "common/name_list.h"

namespace tristream {
namespace {

constexpr std::array fits{
    FitName{"stretch", Fit::stretch},
    FitName{"inside", Fit::inside},
    FitName{"fill", Fit::fill},
};

}  // namespace

std::span<const FitName> fit_names() { return fits; }

std::vector<std::string> fit_name_list() {
  std::vector<std::string> names;
  for (const FitName& f : fits) names.emplace_back(f.name);
  return names;
}

std::string_view fit_name(Fit fit) {
  for (const FitName& f : fits)
    if (f.fit == fit) return f.name;
  return "?";
}

std::optional<Fit> find_fit(std::string_view name) {
  for (const FitName& f : fits)
    if (f.name == name) return f.fit;
  return std::nullopt;
}

Fit parse_fit(std::string_view name) {
  if (const std::optional<Fit> fit = find_fit(name)) return *fit;
  throw UsageError("fit must be " + name_list(fits) + ", not \"" + std::string(name) + "\"");
}

}  // namespace tristream
