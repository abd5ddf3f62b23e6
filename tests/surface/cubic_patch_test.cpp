#include "surface/cubic_patch.hpp"

#include <gtest/gtest.h>

#include <random>

#include "surface/patch_closest_point.hpp"
#include "surface_test_meshes.hpp"

namespace hocav {
namespace {

template <int D>
CubicPatch<D> random_patch(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  CubicPatch<D> patch;
  for (Vec<D>& point : patch.control)
    for (int i = 0; i < D; ++i) point[i] = coordinate(random);
  return patch;
}

// A mildly bent patch: the vertices of a unit facet, control points at their straight positions
// moved by up to `bend`.
template <int D>
CubicPatch<D> bent_patch(double bend, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-bend, bend);
  CubicPatch<D> patch;
  patch.control[0] = Vec<D>{};
  for (int i = 1; i < D; ++i) patch.control[i][i - 1] = 1;
  if constexpr (D == 3) patch.control[1] = Vec3{{1, 0.1, 0}};
  for (int e = 0; e < CubicPatch<D>::kEdges; ++e) {
    const Vec<D>& from = patch.vertex(kPatchEdges<D>[e][0]);
    const Vec<D>& to = patch.vertex(kPatchEdges<D>[e][1]);
    patch.edge_point(e, 0) = from + (to - from) * (1.0 / 3);
    patch.edge_point(e, 1) = from + (to - from) * (2.0 / 3);
  }
  if constexpr (D == 3) place_centre_control_point(patch);
  for (int c = D; c < CubicPatch<D>::kControlPoints; ++c)
    for (int i = 0; i < D; ++i) patch.control[c][i] += offset(random);
  return patch;
}

template <int D>
void expect_derivatives_match_finite_differences() {
  const CubicPatch<D> patch = random_patch<D>(7);
  PatchParameters<D> at;
  for (int i = 0; i < D - 1; ++i) at[i] = 0.2 + 0.1 * i;
  const PatchJet<D> jet = evaluate_jet(patch, at);
  const double step = 1e-5;
  for (int a = 0; a < D - 1; ++a) {
    PatchParameters<D> plus = at, minus = at;
    plus[a] += step;
    minus[a] -= step;
    const PatchJet<D> jet_plus = evaluate_jet(patch, plus), jet_minus = evaluate_jet(patch, minus);
    const Vec<D> first = (jet_plus.point - jet_minus.point) * (0.5 / step);
    for (int i = 0; i < D; ++i) EXPECT_NEAR(first[i], jet.first[a][i], 1e-8);
    for (int b = 0; b < D - 1; ++b) {
      const Vec<D> second = (jet_plus.first[b] - jet_minus.first[b]) * (0.5 / step);
      for (int i = 0; i < D; ++i) EXPECT_NEAR(second[i], jet.second[a + b][i], 1e-7) << "a " << a << " b " << b;
    }
  }
}

TEST(SurfaceCubicPatch, CurveDerivativesMatchFiniteDifferences) { expect_derivatives_match_finite_differences<2>(); }
TEST(SurfaceCubicPatch, TriangleDerivativesMatchFiniteDifferences) { expect_derivatives_match_finite_differences<3>(); }

template <int D>
void expect_vertices_and_edge_midpoints() {
  const CubicPatch<D> patch = random_patch<D>(3);
  for (int e = 0; e < CubicPatch<D>::kEdges; ++e) {
    const Vec<D> start = evaluate(patch, testing::patch_edge_parameters<D>(e, 0.0));
    const Vec<D> middle = evaluate(patch, testing::patch_edge_parameters<D>(e, 0.5));
    EXPECT_EQ(start, patch.vertex(kPatchEdges<D>[e][0]));
    EXPECT_LT(norm(middle - edge_curve_midpoint(patch, e)), 1e-15);
    // An edge curve depends on its four control points only: the standard cubic Bézier curve.
    const double s = 0.3, w = 1 - s;
    const Vec<D> bezier = w * w * w * patch.vertex(kPatchEdges<D>[e][0]) + 3 * w * w * s * patch.edge_point(e, 0) +
                          3 * w * s * s * patch.edge_point(e, 1) + s * s * s * patch.vertex(kPatchEdges<D>[e][1]);
    EXPECT_LT(norm(evaluate(patch, testing::patch_edge_parameters<D>(e, s)) - bezier), 1e-15);
  }
}

TEST(SurfaceCubicPatch, CurveEdgeIsACubicBezierCurve) { expect_vertices_and_edge_midpoints<2>(); }
TEST(SurfaceCubicPatch, TriangleEdgesAreCubicBezierCurves) { expect_vertices_and_edge_midpoints<3>(); }

TEST(SurfaceCubicPatch, TangentRules) {
  const Vec3 from{{1, 2, 3}}, to{{2, 2.5, 2}}, normal = Vec3{{1, 1, 1}} * (1 / std::sqrt(3.0));
  const Vec3 in_plane = tangent_in_plane(from, to, normal);
  EXPECT_NEAR(dot(in_plane, normal), 0.0, 1e-15);
  EXPECT_NEAR(norm(in_plane), 1.0, 1e-15);
  // The usual rule (docs/method.md §9): (2 P_i + P_j − ((P_j − P_i)·n) n) / 3.
  const Vec3 third = edge_control_point(from, to, in_plane, TangentLength::kProjectedThird);
  EXPECT_LT(norm(third - (2.0 * from + to - dot(to - from, normal) * normal) * (1.0 / 3)), 1e-15);
  EXPECT_LT(norm(tangent_on_line(from, to, Vec3{{-1, 0, 0}}) - Vec3{{1, 0, 0}}), 1e-15);
  // A straight edge: both lengths give its third.
  const Vec3 along = Vec3{{1, 0.5, -1}} * (1 / 1.5);
  for (TangentLength rule : {TangentLength::kProjectedThird, TangentLength::kCircularArc})
    EXPECT_LT(norm(edge_control_point(from, to, along, rule) - (from + (to - from) * (1.0 / 3))), 1e-15);
}

// An arc of angle θ on the unit circle with its exact end tangents: the circular-arc length puts the
// cubic's midpoint on the circle; the projected third misses it by about 9 θ⁴ / 384.
TEST(SurfaceCubicPatch, CircularArcLengthHitsTheArcMidpoint) {
  for (double theta : {0.2, 0.5, 1.0}) {
    CubicPatch<2> arc;
    arc.control[0] = Vec2{{1, 0}};
    arc.control[1] = Vec2{{std::cos(theta), std::sin(theta)}};
    const Vec2 start_tangent{{0, 1}}, end_tangent{{std::sin(theta), -std::cos(theta)}};
    for (TangentLength rule : {TangentLength::kProjectedThird, TangentLength::kCircularArc}) {
      arc.edge_point(0, 0) = edge_control_point(arc.vertex(0), arc.vertex(1), start_tangent, rule);
      arc.edge_point(0, 1) = edge_control_point(arc.vertex(1), arc.vertex(0), end_tangent, rule);
      const double error = norm(edge_curve_midpoint(arc, 0)) - 1;
      if (rule == TangentLength::kCircularArc)
        EXPECT_NEAR(error, 0.0, 1e-15) << theta;
      else
        EXPECT_NEAR(error, -9 * std::pow(theta, 4) / 384, 0.1 * 9 * std::pow(theta, 4) / 384) << theta;
    }
  }
}

// The closest point on a patch agrees with dense sampling (and is never farther).
template <int D>
void expect_closest_point_matches_sampling() {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-0.5, 1.5);
  const int n = 200;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const CubicPatch<D> patch = bent_patch<D>(0.15, seed);
    Vec<D> x;
    for (int i = 0; i < D; ++i) x[i] = coordinate(random);
    const PatchClosestPoint<D> found = closest_point_on_patch(patch, x);
    EXPECT_LT(norm(evaluate(patch, found.parameters) - found.point), 1e-15);
    double sampled = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= (D == 3 ? n - i : 0); ++j) {
        PatchParameters<D> parameters;
        parameters[0] = double(i) / n;
        if constexpr (D == 3) parameters[1] = double(j) / n;
        sampled = std::min(sampled, norm(evaluate(patch, parameters) - x));
      }
    const double distance = std::sqrt(found.distance2);
    EXPECT_LE(distance, sampled + 1e-12) << "seed " << seed;
    EXPECT_GE(distance, sampled - 1e-3) << "seed " << seed;  // sampling resolution
  }
}

TEST(SurfaceCubicPatch, CurveClosestPointMatchesSampling) { expect_closest_point_matches_sampling<2>(); }
TEST(SurfaceCubicPatch, TriangleClosestPointMatchesSampling) { expect_closest_point_matches_sampling<3>(); }

// Inside the patch the closest point is stationary to rounding: the residual is orthogonal to the
// tangents (Newton's last step, taken without a descent test, is small enough to be exact).
template <int D>
void expect_inner_closest_points_stationary() {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-0.2, 1.2);
  int inner = 0;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const CubicPatch<D> patch = bent_patch<D>(0.15, seed);
    Vec<D> x;
    for (int i = 0; i < D; ++i) x[i] = coordinate(random);
    const PatchClosestPoint<D> found = closest_point_on_patch(patch, x);
    const auto lambda = found.barycentrics();
    if (*std::min_element(lambda.begin(), lambda.end()) < 1e-6) continue;
    ++inner;
    const PatchJet<D> jet = evaluate_jet(patch, found.parameters);
    const Vec<D> residual = jet.point - x;
    for (const Vec<D>& tangent : jet.first)
      EXPECT_LE(std::abs(dot(residual, tangent)), 1e-13 * norm(tangent) * std::max(norm(residual), 1.0)) << "seed " << seed;
  }
  EXPECT_GT(inner, 20);
}

TEST(SurfaceCubicPatch, CurveClosestPointIsStationary) { expect_inner_closest_points_stationary<2>(); }
TEST(SurfaceCubicPatch, TriangleClosestPointIsStationary) { expect_inner_closest_points_stationary<3>(); }

TEST(SurfaceCubicPatch, ClosestPointIsClampedToTheTriangle) {
  const CubicPatch<3> patch = bent_patch<3>(0.0, 1);  // the flat triangle (0,0,0) (1,0.1,0) (0,1,0)
  const PatchClosestPoint<3> beyond_edge = closest_point_on_patch(patch, Vec3{{0.8, 0.8, 0.3}});
  EXPECT_NEAR(beyond_edge.barycentrics()[0], 0.0, 1e-12);
  const PatchClosestPoint<3> beyond_vertex = closest_point_on_patch(patch, Vec3{{-1, -1, 0.2}});
  EXPECT_LT(norm(beyond_vertex.point), 1e-12);
}

}  // namespace
}  // namespace hocav
