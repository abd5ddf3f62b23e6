// The Hausdorff bound as a metric (docs/adaptation.md §The Hausdorff bound): the sizes it asks on
// circles and spheres against the chord-sag formulas, nothing on flat boundaries, and the loop
// bringing a coarse sphere shell within the bound.
#include "adapt/hausdorff_metric.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "adapt/adaptation_loop.hpp"
#include "cases/cubed_sphere_shell.hpp"
#include "cases/polar_annulus.hpp"
#include "cases/structured.hpp"
#include "geom/sym_eigen.hpp"
#include "metric/metric_field.hpp"
#include "surface/analytic_boundary.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

constexpr double kInner = 0.5, kOuter = 1.0;

// Whether v is a boundary vertex of the concentric shell, and on which radius.
template <int D>
double shell_radius(const Mesh<D>& mesh, Index v) {
  const double r = norm(mesh.vertex(v));
  if (std::abs(r - kInner) < 1e-9) return kInner;
  if (std::abs(r - kOuter) < 1e-9) return kOuter;
  return 0;
}

// A metric of sizes 100 every way: coarser than any bound here, which then holds at every boundary
// vertex.
template <int D>
std::vector<SymMat<D>> coarse(const Mesh<D>& mesh) {
  return std::vector<SymMat<D>>(static_cast<std::size_t>(mesh.vertex_count()), SymMat<D>::identity() * 1e-4);
}

// Where the bound asks for a size on a sphere of radius R, its eigenvalues must be the chord-sag
// formula's, μ = 1 / (6 R hausd), along the surface and, by the bound's choice, across it; in 2D
// μ = 1 / (8 R hausd). The edges are coarse (L/R up to 0.3): their sags read the curvature to about
// (L/R)²/16.
template <int D>
void expect_sphere_sizes(const Mesh<D>& mesh, double hausd, int& checked) {
  const AnalyticBoundary<D> geometry = concentric_shell_boundary<D>(kInner, kOuter);
  const std::vector<SymMat<D>> bound = hausdorff_metrics<D>(mesh, geometry, {hausd, 45}, coarse(mesh));
  ASSERT_EQ(bound.size(), static_cast<std::size_t>(mesh.vertex_count()));
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const double radius = shell_radius(mesh, v);
    if (radius == 0) continue;
    const double expected = 1 / ((D == 3 ? 6 : 8) * radius * hausd);
    const SymEigen<D> eigen = spd_eigen(bound[static_cast<std::size_t>(v)]);
    for (int k = 0; k < D; ++k) EXPECT_NEAR(eigen.values[k] / expected, 1, 0.03) << "vertex " << v << " eigenvalue " << k;
    ++checked;
  }
}

TEST(HausdorffMetric, AsksTheChordSagSizesOnSpheres) {
  const std::array<double, 3> radii{kInner, 0.75, kOuter};
  int checked = 0;
  expect_sphere_sizes(generate_cubed_sphere_shell(6, radii), 1e-3, checked);
  EXPECT_EQ(checked, 2 * (6 * 36 + 2));
}

TEST(HausdorffMetric, AsksTheChordSagSizesOnCircles) {
  const std::array<double, 3> radii{kInner, 0.75, kOuter};
  int checked = 0;
  expect_sphere_sizes(generate_polar_annulus(40, radii), 1e-3, checked);
  EXPECT_EQ(checked, 80);
}

// Inside, the bound grows from the boundary at the gradation 1.3: the middle sphere's vertices get
// sizes between the inner sphere's and the outer sphere's, larger than the inner one's.
TEST(HausdorffMetric, GradesTheBoundInside) {
  const std::array<double, 3> radii{kInner, 0.75, kOuter};
  const Mesh<3> mesh = generate_cubed_sphere_shell(6, radii);
  const double hausd = 1e-3;
  const std::vector<SymMat<3>> bound = hausdorff_metrics<3>(mesh, concentric_shell_boundary<3>(kInner, kOuter), {hausd, 45}, coarse(mesh));
  const double inner_size = std::sqrt(6 * kInner * hausd);
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (std::abs(norm(mesh.vertex(v)) - 0.75) > 1e-9) continue;
    const double largest_size = 1 / std::sqrt(spd_eigen(bound[static_cast<std::size_t>(v)]).values[0]);
    EXPECT_GT(largest_size, 1.2 * inner_size) << v;
    EXPECT_LT(largest_size, inner_size + std::log(1.3) * 0.25 * 1.1) << v;
  }
}

// A cube's faces and ridges are straight: its metric is kept bit for bit, whatever hausd.
TEST(HausdorffMetric, LeavesAFlatBoundaryAlone) {
  Mesh<3> mesh = generate_cube(4);
  mesh.build_topology();
  const P3Surrogate<3> geometry(mesh);
  std::vector<SymMat<3>> metrics(static_cast<std::size_t>(mesh.vertex_count()), SymMat<3>::identity() * 4.0);
  const std::vector<SymMat<3>> before = metrics;
  EXPECT_EQ(bound_metrics_by_hausdorff(mesh, metrics, geometry, {1e-6, 45}), 0);
  EXPECT_EQ(metrics, before);
}

// Where the given metric is finer than the bound already, the bound asks for nothing, there nor inside.
TEST(HausdorffMetric, IsNothingWhereTheGivenMetricIsFiner) {
  const std::array<double, 3> radii{kInner, 0.75, kOuter};
  const Mesh<3> mesh = generate_cubed_sphere_shell(6, radii);
  const std::vector<SymMat<3>> fine(static_cast<std::size_t>(mesh.vertex_count()), SymMat<3>::identity() * 1e4);
  const std::vector<SymMat<3>> bound = hausdorff_metrics<3>(mesh, concentric_shell_boundary<3>(kInner, kOuter), {1e-3, 45}, fine);
  const double diagonal_eigenvalue = 1 / (4 * 3.0);  // the box [-1, 1]³: diagonal 2√3
  for (const SymMat<3>& metric : bound) EXPECT_NEAR(spd_eigen(metric).values[2], diagonal_eigenvalue, 1e-12);
}

// A metric of layers around the origin: size `across` along the radius, 100 along the spheres.
template <int D>
std::vector<SymMat<D>> layered(const Mesh<D>& mesh, double across) {
  std::vector<SymMat<D>> metrics;
  for (const Vec<D>& x : mesh.vertices()) {
    const Vec<D> n = x * (1 / norm(x));
    SymMat<D> m = SymMat<D>::identity() * 1e-4;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j <= i; ++j) m(i, j) += (1 / (across * across) - 1e-4) * n[i] * n[j];
    metrics.push_back(m);
  }
  return metrics;
}

// Whether two lists of metrics agree to round-off (each entry within 1e-9 of the matrix's largest).
template <int D>
bool agree(const std::vector<SymMat<D>>& a, const std::vector<SymMat<D>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t v = 0; v < a.size(); ++v)
    for (int i = 0; i < D; ++i)
      for (int j = 0; j <= i; ++j)
        if (std::abs(a[v](i, j) - b[v](i, j)) > 1e-9 * spd_eigen(b[v]).values[D - 1]) return false;
  return true;
}

// The relative bound: at each boundary vertex the distance is also at most C times the smallest
// size the metric asks there, so a loose hausd with C = 0.5 over layers of 0.004 asks what hausd
// 0.002 asks, and nothing without C.
TEST(HausdorffMetric, TheRelativeBoundIsTheBoundOfThatFractionOfTheSizeAcross) {
  const std::array<double, 3> radii{kInner, 0.75, kOuter};
  const Mesh<3> mesh = generate_cubed_sphere_shell(6, radii);
  const AnalyticBoundary<3> geometry = concentric_shell_boundary<3>(kInner, kOuter);
  const std::vector<SymMat<3>> given = layered(mesh, 0.004);
  EXPECT_TRUE(agree(hausdorff_metrics<3>(mesh, geometry, {100, 45, 0.5}, given), hausdorff_metrics<3>(mesh, geometry, {0.002, 45}, given)));
  const double diagonal_eigenvalue = 1 / (4 * 3.0);  // asks nothing: the sizes of the box's diagonal
  for (const SymMat<3>& metric : hausdorff_metrics<3>(mesh, geometry, {100, 45}, given))
    EXPECT_NEAR(spd_eigen(metric).values[2], diagonal_eigenvalue, 1e-12);
  // Where C times the given metric's smallest size is above hausd, hausd holds, bit for bit.
  EXPECT_EQ(hausdorff_metrics<3>(mesh, geometry, {1e-3, 45, 0.5}, given), hausdorff_metrics<3>(mesh, geometry, {1e-3, 45}, given));
}

TEST(HausdorffMetric, WithinBoundIsTheIntersectionOrTheMetricItself) {
  const SymMat<2> fine = SymMat<2>::identity() * 100.0;
  const SymMat<2> bound = SymMat<2>::from_diagonal({{50, 200}});
  EXPECT_EQ(within_bound(fine, SymMat<2>::identity() * 10.0), fine);  // already finer: the same bits
  const SymMat<2> both = within_bound(fine, bound);
  EXPECT_NEAR(both(0, 0), 100, 1e-9);
  EXPECT_NEAR(both(1, 1), 200, 1e-9);
  EXPECT_NEAR(both(1, 0), 0, 1e-9);
}

// The largest and mean distance of the boundary facets' centroids from the true spheres.
std::array<double, 2> centroid_sag(const Mesh<3>& mesh) {
  double largest = 0, sum = 0;
  Index count = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_removed(f)) continue;
    Vec3 centroid{};
    for (Index v : mesh.facet(f)) centroid += (1.0 / 3) * mesh.vertex(v);
    const double radius = mesh.facet_ref(f) == 1 ? kInner : kOuter;
    const double sag = std::abs(norm(centroid) - radius);
    largest = std::max(largest, sag);
    sum += sag;
    ++count;
  }
  return {largest, sum / count};
}

// A coarse shell adapted to sizes of 0.4: its facets sag far beyond hausd; with the bound, the loop
// refines the spheres until they are within it (a unit facet's centroid at hausd, edges up to √2 in
// the metric: up to 2 hausd). Measured: 1.4 and 0.9 hausd (max, mean), 20 and 6.6 without.
std::array<double, 2> adapted_sag(double hausd, Index& bounded) {
  const std::array<double, 2> radii{kInner, kOuter};
  Mesh<3> mesh = generate_cubed_sphere_shell(4, radii);
  mesh.build_topology();
  const AnalyticBoundary<3> geometry = concentric_shell_boundary<3>(kInner, kOuter);
  std::vector<SymMat<3>> metrics(static_cast<std::size_t>(mesh.vertex_count()), SymMat<3>::identity() * (1 / 0.16));
  bounded = hausd > 0 ? bound_metrics_by_hausdorff(mesh, metrics, geometry, {hausd, 45}) : 0;
  const MetricField<3> field(mesh, metrics);
  AdaptationSettings settings;
  settings.hausd = hausd;
  adapt_to_metric(mesh, AdaptationMetric<3>(field, SizeBounds{}), &geometry, settings);
  return centroid_sag(mesh);
}

TEST(HausdorffBound, BringsACoarseSphereShellWithinHausd) {
  const double hausd = 0.005;
  Index bounded = 0;
  const auto [largest, mean] = adapted_sag(hausd, bounded);
  EXPECT_GT(bounded, 0);
  EXPECT_LT(mean, 1.2 * hausd);
  EXPECT_LT(largest, 2 * hausd);
  const auto [largest_unbounded, mean_unbounded] = adapted_sag(0, bounded);
  EXPECT_GT(mean_unbounded, 4 * hausd);  // without the bound the facets sag far more
  EXPECT_GT(largest_unbounded, 10 * hausd);
}

}  // namespace
}  // namespace hocav
