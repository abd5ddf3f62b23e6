// The checks the generators share on their parameters, with messages that name the option and the
// value given.
#pragma once

#include <cmath>
#include <span>
#include <sstream>
#include <string>

#include "base/error.hpp"
#include "base/index.hpp"
#include "base/memory_budget.hpp"

namespace hocav {

// A number as the user would type it (shortest of the usual forms: 0.5, 1e-06).
inline std::string number_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// Throws Error unless 0 < inner < outer, both finite.
inline void check_shell_radii(double inner_radius, double outer_radius) {
  if (!(std::isfinite(inner_radius) && std::isfinite(outer_radius) && 0 < inner_radius && inner_radius < outer_radius))
    throw Error("the radii must satisfy 0 < r-in < r-out, got r-in = " + number_text(inner_radius) +
                " and r-out = " + number_text(outer_radius));
}

// Throws Error naming `what` unless value > 0 and finite.
inline void check_positive(const std::string& what, double value) {
  if (!(std::isfinite(value) && value > 0)) throw Error(what + " must be positive, got " + number_text(value));
}

// The most elements a generated case may have.
inline constexpr double kMaximumCaseElements = 5e7;

// Throws Error unless a case meshed at size h = `size`, with about `elements` elements, stays within
// kMaximumCaseElements and fits in memory.
inline void check_case_size(double size, double elements) {
  if (elements > kMaximumCaseElements)
    throw Error("size h = " + number_text(size) + " is too small: the mesh would exceed 50 million elements");
  check_memory_fits("size h = " + number_text(size), elements, kMeshBytesPerElement);
}

// Throws Error unless there are at least two layer radii, finite and increasing from a positive one.
inline void check_layer_radii(std::span<const double> radii) {
  if (radii.size() < 2) throw Error("a layered shell needs at least two radii, got " + std::to_string(radii.size()));
  for (std::size_t i = 0; i < radii.size(); ++i)
    if (!(std::isfinite(radii[i]) && radii[i] > (i == 0 ? 0.0 : radii[i - 1])))
      throw Error("the layer radii must increase from a positive one: radius " + one_based(i) + " is " + number_text(radii[i]));
}

}  // namespace hocav
