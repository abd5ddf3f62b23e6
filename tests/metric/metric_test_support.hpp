// Meshes and metrics shared by the tests of the metric sources (implied, surface, gradation, Hessian).
#pragma once

#include <random>

#include "../geom/random_matrices.hpp"
#include "cases/structured.hpp"
#include "geom/sym_mat.hpp"
#include "metric/analytic_metric.hpp"
#include "metric/metric_field.hpp"

namespace hocav::metric_test {

template <int D>
Mesh<D> unit_mesh(int cells_per_side) {
  if constexpr (D == 2)
    return generate_square(cells_per_side);
  else
    return generate_cube(cells_per_side);
}

// The vertex at x (kNoIndex: none).
template <int D>
Index vertex_at(const Mesh<D>& mesh, const Vec<D>& x) {
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (norm(mesh.vertex(v) - x) < 1e-12) return v;
  return kNoIndex;
}

// The structured unit square or cube with its interior vertices moved at random by up to
// `amplitude` cells along each axis (amplitude < 0.25 keeps every element positive).
template <int D>
Mesh<D> perturbed_unit_mesh(int cells_per_side, double amplitude, unsigned seed = 7) {
  Mesh<D> mesh = unit_mesh<D>(cells_per_side);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> shift(-amplitude / cells_per_side, amplitude / cells_per_side);
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    Vec<D>& x = mesh.vertex(v);
    bool interior = true;
    for (int i = 0; i < D; ++i) interior = interior && x[i] > 1e-12 && x[i] < 1 - 1e-12;
    if (interior)
      for (int i = 0; i < D; ++i) x[i] += shift(random);
  }
  return mesh;
}

// A random SPD metric with sizes between h and h · size_ratio along random axes.
template <int D>
SymMat<D> random_metric(std::mt19937_64& random, double h, double size_ratio) {
  std::uniform_real_distribution<double> log_size(0, std::log(size_ratio));
  Vec<D> eigenvalues;
  for (int i = 0; i < D; ++i) {
    double size = h * std::exp(log_size(random));
    eigenvalues[i] = 1 / (size * size);
  }
  return geom_test::random_with_eigenvalues<D>(random, eigenvalues);
}

// The edge optimizer's test field (its benchmark's): the shear layer (shear-circle in 2D, shear-sphere in 3D)
// of radius 0.75 around the origin and width 0.1, sizes 0.1 along it and 0.1/300 across, at mesh's vertices.
template <int D>
MetricField<D> shear_layer_field(const Mesh<D>& mesh) {
  AnalyticMetricSpec spec;
  spec.name = D == 2 ? "shear-circle" : "shear-sphere";
  spec.h_max = 0.1;
  spec.h_min = spec.h_max / 300;
  spec.width = 0.1;
  return MetricField<D>(mesh, analytic_metric_at_vertices<D>(spec, mesh));
}

}  // namespace hocav::metric_test
