#include "cases/radial_layers.hpp"

#include <algorithm>
#include <cmath>

#include "cases/parameter_checks.hpp"

namespace hocav {
namespace {

constexpr double kMaximumLayers = 1e6;

void check_layer_count(double count) {
  if (count > kMaximumLayers)
    throw Error("the shell would have more than " + number_text(kMaximumLayers) + " layers: the layers are too thin");
}

// Appends `count` layers between radii.back() and `end`, equal in r (linear) or in ln r.
void append_layers(std::vector<double>& radii, double end, long count, bool logarithmic) {
  const double start = radii.back();
  check_layer_count(static_cast<double>(radii.size()) + static_cast<double>(count));
  for (long i = 1; i < count; ++i) {
    const double fraction = static_cast<double>(i) / static_cast<double>(count);
    radii.push_back(logarithmic ? start * std::pow(end / start, fraction) : start + (end - start) * fraction);
  }
  radii.push_back(end);
}

// A boundary layer growing from a wall: where its last layer ends and the next one's thickness.
struct Front {
  double position;
  double thickness;
  int count = 0;
  bool growing = true;
};

}  // namespace

std::vector<double> layer_radii(const ShellLayering& layering, double angular_step) {
  check_shell_radii(layering.inner_radius, layering.outer_radius);
  check_positive("the angular step", angular_step);
  if (!(std::isfinite(layering.growth) && layering.growth >= 1))
    throw Error("growth must be at least 1, got " + number_text(layering.growth));
  if (!(std::isfinite(layering.first_layer) && layering.first_layer >= 0))
    throw Error("first-layer must be positive (or 0 for the default), got " + number_text(layering.first_layer));
  if (layering.layers < 0) throw Error("layers must be at least 0, got " + std::to_string(layering.layers));

  // Radii of the inner front upward, and of the outer front downward.
  std::vector<double> from_inner{layering.inner_radius}, from_outer{layering.outer_radius};
  const double first = layering.first_layer > 0 ? layering.first_layer : layering.inner_radius * angular_step / kDefaultWallAspect;
  Front fronts[2] = {{layering.inner_radius, first, 0, layering.walls != LayerWalls::kNone},
                     {layering.outer_radius, first, 0, layering.walls == LayerWalls::kBoth}};
  bool met = false;
  for (;;) {
    for (Front& front : fronts)
      if (layering.layers > 0 ? front.count >= layering.layers
                              : layering.walls == LayerWalls::kInner && front.thickness >= front.position * angular_step)
        front.growing = false;
    const int next = fronts[1].growing && (!fronts[0].growing || fronts[1].thickness < fronts[0].thickness) ? 1 : 0;
    Front &front = fronts[next], &other = fronts[1 - next];
    if (!front.growing) break;
    // Room for this layer and one more of either front, or the fronts have met.
    if (fronts[1].position - fronts[0].position < front.thickness + (other.growing ? other.thickness : front.thickness)) {
      met = true;
      break;
    }
    front.position += next == 0 ? front.thickness : -front.thickness;
    (next == 0 ? from_inner : from_outer).push_back(front.position);
    front.thickness *= layering.growth;
    ++front.count;
    check_layer_count(static_cast<double>(from_inner.size() + from_outer.size()));
  }

  // The gap between the fronts: one or two closing layers where they met, else isotropic layers.
  const double low = fronts[0].position, high = fronts[1].position;
  const double closing = fronts[0].thickness + (fronts[1].growing ? fronts[1].thickness : fronts[0].thickness);
  const double count = met ? 2 * (high - low) / closing : std::log(high / low) / angular_step;
  check_layer_count(count);
  append_layers(from_inner, high, std::max(1L, std::lround(count)), !met);
  from_inner.insert(from_inner.end(), from_outer.rbegin() + 1, from_outer.rend());
  return from_inner;
}

std::vector<double> unit_layer_radii(double inner_radius, double outer_radius, const std::function<double(double)>& size) {
  check_shell_radii(inner_radius, outer_radius);
  auto size_at = [&size](double r) {
    const double h = size(r);
    if (!(std::isfinite(h) && h > 0)) throw Error("the radial size must be positive, got " + number_text(h) + " at r = " + number_text(r));
    return h;
  };
  // Samples of ∫ dr / h from r_in, at least kSamples and at least 8 per layer; a first pass on the
  // kSamples alone refuses far too many layers before the fine samples take their memory.
  constexpr double kSamples = 20000;
  const double coarse_step = (outer_radius - inner_radius) / kSamples;
  double estimate = 0;
  for (int i = 0; i < static_cast<int>(kSamples); ++i) estimate += coarse_step / size_at(inner_radius + (i + 0.5) * coarse_step);
  check_layer_count(estimate);
  std::vector<double> samples{inner_radius}, integral{0};
  double h = size_at(inner_radius);
  while (samples.back() < outer_radius) {
    const double r = std::min(outer_radius, samples.back() + std::min(coarse_step, h / 8));
    const double next_h = size_at(r);
    integral.push_back(integral.back() + 0.5 * (1 / h + 1 / next_h) * (r - samples.back()));
    samples.push_back(r);
    h = next_h;
    check_layer_count(integral.back());
  }
  const long count = std::max(1L, std::lround(integral.back()));
  std::vector<double> radii{inner_radius};
  std::size_t sample = 1;
  for (long j = 1; j < count; ++j) {
    const double wanted = integral.back() * static_cast<double>(j) / static_cast<double>(count);
    while (integral[sample] < wanted) ++sample;
    const double fraction = (wanted - integral[sample - 1]) / (integral[sample] - integral[sample - 1]);
    radii.push_back(samples[sample - 1] + fraction * (samples[sample] - samples[sample - 1]));
  }
  radii.push_back(outer_radius);
  return radii;
}

}  // namespace hocav
