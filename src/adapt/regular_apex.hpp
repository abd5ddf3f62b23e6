// The smoothing's repair target (docs/adaptation.md §Smoothing): over the centroid of the face
// opposite the vertex, along the face's Euclidean normal, at the altitude (measured in the metric)
// of the regular simplex whose edges have the face's mean length in the metric. In an isotropic
// metric that is where the vertex makes its element regular. (The normal in the metric, M⁻¹ n,
// makes the element regular in any metric, but as a target it lowered the minimum qualities of the
// side-by-side cases: docs/benchmarks.md, twenty-seventh session.)
#pragma once

#include <array>
#include <cmath>

#include "geom/sym_mat.hpp"
#include "geom/vec.hpp"

namespace hocav {

// `face`: the D vertices opposite the moving one; `side`: a point on the side where the apex goes
// (the vertex itself).
template <int D>
Vec<D> regular_apex(const std::array<Vec<D>, D>& face, const Vec<D>& side, const SymMat<D>& metric) {
  Vec<D> centroid{};
  for (const Vec<D>& p : face) centroid = centroid + (1.0 / D) * p;
  Vec<D> direction;
  if constexpr (D == 2)
    direction = Vec<D>{{face[0][1] - face[1][1], face[1][0] - face[0][0]}};
  else
    direction = cross(face[1] - face[0], face[2] - face[0]);
  if (dot(direction, side - centroid) < 0) direction = -1.0 * direction;
  double mean_length = 0;
  int edges = 0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < i; ++j, ++edges) mean_length += std::sqrt(quadratic_form(metric, face[i] - face[j]));
  mean_length /= edges;
  const double altitude = (D == 2 ? std::sqrt(3.0) / 2 : std::sqrt(2.0 / 3)) * mean_length;  // in the metric
  const double direction_length = std::sqrt(quadratic_form(metric, direction));
  return direction_length > 0 ? centroid + (altitude / direction_length) * direction : side;
}

}  // namespace hocav
