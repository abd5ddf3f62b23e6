#include "cases/target_resolution.hpp"

#include <cmath>
#include <string>

#include "cases/parameter_checks.hpp"

namespace hocav {

int resolution_for_target(const char* what, double target, int minimum, const std::function<double(int)>& elements) {
  if (!(std::isfinite(target) && target >= 1 && target <= kMaximumCaseElements))
    throw Error(std::string(what) + " must be between 1 and " + number_text(kMaximumCaseElements) + ", got " + number_text(target));
  // The smallest n reaching the target: doubling, then bisection.
  int low = minimum, high = minimum;
  while (elements(high) < target) {
    low = high;
    high *= 2;
  }
  while (high - low > 1) {
    const int middle = low + (high - low) / 2;
    (elements(middle) < target ? low : high) = middle;
  }
  if (high == minimum) return minimum;
  return std::log(target / elements(low)) < std::log(elements(high) / target) ? low : high;
}

LayeredResolution layered_resolution_for_target(const char* what, double target, int minimum, const ShellLayering& layering,
                                                double (*angular_step)(int), double (*elements)(int, std::size_t)) {
  const int resolution = resolution_for_target(what, target, minimum,
                                               [&](int n) { return elements(n, layer_radii(layering, angular_step(n)).size()); });
  return {resolution, layer_radii(layering, angular_step(resolution))};
}

}  // namespace hocav
