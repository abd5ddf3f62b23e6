// The radii of the layers of a structured shell (the polar annulus, the cubed-sphere shell): the
// layers of vertices lie on circles/spheres r_0 = r_in < r_1 < ... < r_L = r_out, and the grid's
// angle between neighbouring radial lines, the angular step, fixes the tangential size r * step.
//   isotropic       r_i = r_in (r_out / r_in)^(i / L), L = round(ln(r_out / r_in) / step): every
//                   layer is as thick as its cells are wide (r_{i+1} − r_i ≈ r_i step)
//   boundary layer  thicknesses t0, t0 q, t0 q², ... grown from the inner circle/sphere, or from
//                   both, then the isotropic spacing up to the other wall (or up to the meeting)
//   metric-unit     equal steps of ∫ dr / h(r) for a radial size function h
#pragma once

#include <functional>
#include <vector>

namespace hocav {

enum class LayerWalls { kNone, kInner, kBoth };

struct ShellLayering {
  double inner_radius = 0.5;
  double outer_radius = 1.0;
  LayerWalls walls = LayerWalls::kNone;
  // Thickness of the layer on a wall; 0 = the inner wall's tangential size / kDefaultWallAspect.
  double first_layer = 0;
  // Ratio of the thicknesses of neighbouring boundary layers (>= 1).
  double growth = 1.2;
  // Boundary layers per wall; 0 = grow them until their thickness reaches the tangential size
  // (walls kInner) or until the two fronts meet (walls kBoth).
  int layers = 0;
};

// Tangential size / first-layer thickness on the inner wall when first_layer is 0.
inline constexpr double kDefaultWallAspect = 50;

// The radii of the layers for a grid of the given angular step (radians). With walls kBoth and no
// layer cap the fronts advance in turn, the thinner one first, until the gap left cannot hold the
// next layer of each; the gap is closed by one or two layers of about their thickness. Throws
// Error for radii not 0 < r_in < r_out, a non-positive step or first layer, a growth below 1, or
// more than a million layers.
std::vector<double> layer_radii(const ShellLayering& layering, double angular_step);

// Radii that make the radial size function h unit: L = round(∫ dr / h) layers (at least one) in
// equal steps of that integral between r_in and r_out (trapezoid rule on at least 20000 steps,
// and at least 8 per layer).
std::vector<double> unit_layer_radii(double inner_radius, double outer_radius, const std::function<double(double)>& size);

}  // namespace hocav
