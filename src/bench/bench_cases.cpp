#include "bench/bench_cases.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "mesh/measure.hpp"
#include "metric/analytic_metric.hpp"
#include "metric/gradation.hpp"
#include "metric/implied_metric.hpp"
#include "metric/surface_metric.hpp"

namespace hocav {
namespace {

// The unit cube has 6 n³ tetrahedra for n cells per side; h = 1/(n − ½) asks for exactly n.
CaseValues cube_for_target(double target) {
  const double cells = std::max(1.0, std::round(std::cbrt(target / 6)));
  return {{"h", 1 / (cells - 0.5)}};
}

CaseValues tetrahedra_for_target(double target) { return {{"target-tets", target}}; }
CaseValues triangles_for_target(double target) { return {{"target-triangles", target}}; }

// gmsh's sphere shell (radii 0.5, 1) gave 137,062 tetrahedra at h = 0.05; the count goes as h⁻³.
CaseValues sphere_shell_for_target(double target) { return {{"h", 0.05 * std::cbrt(137062 / target)}}; }

// The demo's boundary sizes (docs/usage.md), graded into the volume as `hocav metric --surface` does.
constexpr double kShellNormalSize = 0.01, kShellTangentialSize = 0.1, kShellGradation = 1.5;

std::vector<BenchCase> make_cases() {
  return {
      {"cubed-shell", "cubed-shell", tetrahedra_for_target, BenchMetric::kSurfaceGraded, "p3", 5e7,
       "structured isotropic sphere shell, surface metric 0.01/0.1 graded by 1.5 (the paper's Meshes 1)"},
      {"cubed-shell-bl-inner", "cubed-shell-bl-inner", tetrahedra_for_target, BenchMetric::kImplied, "p3", 5e7,
       "sphere shell with a boundary layer on the inner sphere, in its implied metric"},
      {"cubed-shell-bl-both", "cubed-shell-bl-both", tetrahedra_for_target, BenchMetric::kImplied, "p3", 5e7,
       "sphere shell with boundary layers on both spheres meeting inside, in its implied metric"},
      {"cube-shear", "cube", cube_for_target, BenchMetric::kShear, "p3", 5e7,
       "structured unit cube in the shear-sphere layer (radius 0.75 around a corner, anisotropy 100)"},
      {"sphere-shell", "sphere-shell", sphere_shell_for_target, BenchMetric::kSurfaceGraded, "p3", 1e6,
       "gmsh's unstructured isotropic sphere shell, surface metric 0.01/0.1 graded by 1.5 (the demo)"},
      {"annulus-shear", "polar-annulus", triangles_for_target, BenchMetric::kShear, "p3", 5e7,
       "2D: structured annulus in the shear-circle layer (the paper's Fig. 1 field)"},
      {"annulus-bl-inner", "polar-annulus-bl-inner", triangles_for_target, BenchMetric::kImplied, "p3", 5e7,
       "2D: annulus with a boundary layer on the inner circle, in its implied metric"},
  };
}

}  // namespace

const std::vector<BenchCase>& bench_cases() {
  static const std::vector<BenchCase> cases = make_cases();
  return cases;
}

const BenchCase& find_bench_case(const std::string& name) {
  std::string known;
  for (const BenchCase& bench_case : bench_cases()) {
    if (bench_case.name == name) return bench_case;
    known += (known.empty() ? "" : ", ") + bench_case.name;
  }
  throw Error("unknown bench case '" + name + "' (known: " + known + ")");
}

template <int D>
std::vector<SymMat<D>> bench_metric(BenchMetric metric, const Mesh<D>& mesh) {
  switch (metric) {
    case BenchMetric::kShear: {
      AnalyticMetricSpec spec;
      spec.name = D == 2 ? "shear-circle" : "shear-sphere";
      return analytic_metric_at_vertices(spec, mesh);
    }
    case BenchMetric::kSurfaceGraded: {
      const SurfaceSizes sizes{kShellNormalSize, kShellTangentialSize, bounding_box_diagonal(mesh)};
      std::vector<SymMat<D>> metrics = surface_metric_at_vertices(mesh, sizes);
      grade_metrics(mesh, metrics, GradationOptions{kShellGradation});
      return metrics;
    }
    case BenchMetric::kImplied: return implied_metric_at_vertices(mesh);
  }
  throw Error("internal error: unknown bench metric");
}

template std::vector<SymMat<2>> bench_metric(BenchMetric, const Mesh<2>&);
template std::vector<SymMat<3>> bench_metric(BenchMetric, const Mesh<3>&);

}  // namespace hocav
