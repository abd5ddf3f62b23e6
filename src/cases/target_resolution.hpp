// Picking a structured case's resolution (cells per side, sectors) from a wanted element count.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "cases/parameter_checks.hpp"
#include "cases/radial_layers.hpp"

namespace hocav {

// The resolution n >= minimum whose element count elements(n) is nearest `target` in ratio,
// elements being non-decreasing in n. Throws Error naming `what` (e.g. "target-tets") for a
// target below 1 or above kMaximumCaseElements.
int resolution_for_target(const char* what, double target, int minimum, const std::function<double(int)>& elements);

// A layered shell's resolution and layer radii for a target element count, given the grid's
// angular step and element count as functions of the resolution (and of the number of radii).
struct LayeredResolution {
  int resolution = 0;
  std::vector<double> radii;
};
LayeredResolution layered_resolution_for_target(const char* what, double target, int minimum, const ShellLayering& layering,
                                                double (*angular_step)(int), double (*elements)(int resolution, std::size_t radii));

}  // namespace hocav
