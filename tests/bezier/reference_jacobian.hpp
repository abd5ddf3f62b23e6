// Test support for src/bezier: the Jacobian determinant of a P2 element computed independently of
// the Bézier machinery (derivatives of the P2 Lagrange shape functions), dense sampling of it, and
// random elements.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "bezier/p2_element.hpp"
#include "geom/barycentric.hpp"

namespace hocav::bezier_test {

// det(∂F/∂ξ) at barycentrics λ (reference axes ξ_k = λ_k). Shape functions: vertex i
// φ_i = λ_i(2λ_i − 1), edge (i, j) φ = 4 λ_i λ_j; with ∂λ_i/∂ξ_k = δ_ik − δ_i0.
template <int D>
double reference_jacobian(const P2Element<D>& element, const Barycentrics<D>& lambda) {
  auto dlambda = [](int i, int k) { return (i == k ? 1.0 : 0.0) - (i == 0 ? 1.0 : 0.0); };
  double f[D][D] = {};  // f[r][k] = ∂F_r/∂ξ_(k+1)
  for (int k = 1; k <= D; ++k) {
    for (int i = 0; i <= D; ++i)
      for (int r = 0; r < D; ++r) f[r][k - 1] += element.vertex(i)[r] * (4.0 * lambda[i] - 1.0) * dlambda(i, k);
    for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
      const int i = edge_vertices<D>(edge)[0], j = edge_vertices<D>(edge)[1];
      const double derivative = 4.0 * (dlambda(i, k) * lambda[j] + lambda[i] * dlambda(j, k));
      for (int r = 0; r < D; ++r) f[r][k - 1] += element.edge_node(edge)[r] * derivative;
    }
  }
  if constexpr (D == 2)
    return f[0][0] * f[1][1] - f[0][1] * f[1][0];
  else
    return f[0][0] * (f[1][1] * f[2][2] - f[1][2] * f[2][1]) - f[0][1] * (f[1][0] * f[2][2] - f[1][2] * f[2][0]) +
           f[0][2] * (f[1][0] * f[2][1] - f[1][1] * f[2][0]);
}

struct SampledRange {
  double min, max;
};

// Min and max of J over the lattice of spacing 1/resolution on the reference simplex.
template <int D>
SampledRange sample_jacobian(const P2Element<D>& element, int resolution) {
  SampledRange range{1e300, -1e300};
  auto visit = [&](const Barycentrics<D>& lambda) {
    const double j = reference_jacobian(element, lambda);
    range.min = std::min(range.min, j);
    range.max = std::max(range.max, j);
  };
  const double h = 1.0 / resolution;
  for (int a = 0; a <= resolution; ++a)
    for (int b = 0; a + b <= resolution; ++b) {
      if constexpr (D == 2) {
        visit({(resolution - a - b) * h, a * h, b * h});
      } else {
        for (int c = 0; a + b + c <= resolution; ++c) visit({(resolution - a - b - c) * h, a * h, b * h, c * h});
      }
    }
  return range;
}

template <int D>
Barycentrics<D> random_barycentrics(std::mt19937& random) {
  std::exponential_distribution<double> exponential(1.0);  // normalized exponentials: uniform on the simplex
  Barycentrics<D> lambda;
  double sum = 0.0;
  for (double& l : lambda) sum += (l = exponential(random));
  for (double& l : lambda) l /= sum;
  return lambda;
}

// A random straight element (coordinates in [-1, 1]) with its edge nodes at the midpoints.
template <int D>
P2Element<D> random_straight_element(std::mt19937& random) {
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  P2Element<D> element;
  for (int i = 0; i <= D; ++i)
    for (int r = 0; r < D; ++r) element.nodes[i][r] = coordinate(random);
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    element.nodes[D + 1 + edge] = 0.5 * (element.vertex(ends[0]) + element.vertex(ends[1]));
  }
  return element;
}

// Moves every edge node by a random vector of length up to `amplitude` times the edge's length.
template <int D>
P2Element<D> curve_randomly(P2Element<D> element, double amplitude, std::mt19937& random) {
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    const double length = norm(element.vertex(ends[1]) - element.vertex(ends[0]));
    Vec<D> offset;
    for (int r = 0; r < D; ++r) offset[r] = coordinate(random);
    element.nodes[D + 1 + edge] += (amplitude * length / std::sqrt(double(D))) * offset;
  }
  return element;
}

// A regular unit simplex with every vertex coordinate jittered by up to 0.15 (so well shaped and
// positive) at a random place, curved by `amplitude`.
template <int D>
P2Element<D> random_curved_element(double amplitude, std::mt19937& random) {
  std::uniform_real_distribution<double> jitter(-0.15, 0.15), place(-1.0, 1.0);
  P2Element<D> element;
  if constexpr (D == 2)
    element.nodes = {Vec2{{0.0, 0.0}}, Vec2{{1.0, 0.0}}, Vec2{{0.5, std::sqrt(3.0) / 2}}};
  else
    element.nodes = {Vec3{{0.0, 0.0, 0.0}}, Vec3{{1.0, 0.0, 0.0}}, Vec3{{0.5, std::sqrt(3.0) / 2, 0.0}},
                     Vec3{{0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3.0)}}};
  Vec<D> offset;
  for (int r = 0; r < D; ++r) offset[r] = place(random);
  for (int i = 0; i <= D; ++i)
    for (int r = 0; r < D; ++r) element.nodes[i][r] += offset[r] + jitter(random);
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    element.nodes[D + 1 + edge] = 0.5 * (element.vertex(ends[0]) + element.vertex(ends[1]));
  }
  return curve_randomly(element, amplitude, random);
}

}  // namespace hocav::bezier_test
