// Tick marks for a chart axis or a colour bar: round values (1, 2 or 5 times a power of ten apart)
// and short labels for them.
#pragma once

#include <string>
#include <vector>

namespace hocav {

// The multiples of a round step (the one nearest (upper − lower) / target) within [lower, upper]:
// about `target` of them. Empty when lower > upper or either is not finite.
std::vector<double> round_ticks(double lower, double upper, int target = 5);

// The shortest "%g" form of a tick value; values within 1e-12 of the step of zero print as "0".
std::string tick_label(double value);

}  // namespace hocav
