// Picking a structured case's resolution (cells per side, sectors) from a wanted element count.
#pragma once

#include <functional>

namespace hocav {

// The largest element count a target may ask for.
inline constexpr double kMaximumTargetElements = 5e7;

// The resolution n >= minimum whose element count elements(n) is nearest `target` in ratio,
// elements being non-decreasing in n. Throws Error naming `what` (e.g. "target-tets") for a
// target below 1 or above kMaximumTargetElements.
int resolution_for_target(const char* what, double target, int minimum, const std::function<double(int)>& elements);

}  // namespace hocav
