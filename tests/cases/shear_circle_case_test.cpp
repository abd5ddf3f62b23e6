#include "cases/shear_circle_case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/error.hpp"
#include "shell_test_support.hpp"

namespace hocav {
namespace {

AnalyticMetricSpec shear_circle() {
  AnalyticMetricSpec spec;
  spec.name = "shear-circle";
  return spec;
}

// The straight edge's length in the metric at its midpoint.
double metric_length(const AnalyticMetricSpec& spec, const Vec2& a, const Vec2& b) {
  const SymMat<2> m = analytic_metric<2>(spec, 0.5 * (a + b));
  const Vec2 d = b - a;
  return std::sqrt(m(0, 0) * d[0] * d[0] + 2 * m(0, 1) * d[0] * d[1] + m(1, 1) * d[1] * d[1]);
}

TEST(ShearCircleCase, IsAUnitMeshOfTheMetric) {
  const AnalyticMetricSpec spec = shear_circle();  // r0 0.75, width 0.05, h-min 0.001, h-max 0.1
  Mesh<2> mesh = generate_shear_circle_annulus(0.5, 1.0, spec);
  shell_test::expect_valid_shell(mesh, 0.5, 1.0);
  const Index sectors = mesh.facet_count() / 2;
  EXPECT_EQ(sectors, static_cast<Index>(std::ceil(2 * std::numbers::pi * 0.75 / 0.1)));
  // Every edge is of unit length within the factor the fixed sector count leaves (tangential
  // edges grow with r: 2/3 at r_in, 4/3 at r_out) and the diagonals (up to sqrt(1 + (4/3)²)).
  mesh.build_edges();
  double radial_total = 0;
  int radial = 0;
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    const auto [a, b] = mesh.edge_vertices(e);
    const double length = metric_length(spec, mesh.vertex(a), mesh.vertex(b));
    EXPECT_GT(length, 0.6) << "edge " << e;
    EXPECT_LT(length, 1.75) << "edge " << e;
    if ((b - a) == sectors) {  // same sector, next layer
      radial_total += length;
      ++radial;
    }
  }
  EXPECT_NEAR(radial_total / radial, 1, 0.02);
  // The thinnest layer is h-min thick and sits at r0.
  double thinnest = 1, where = 0;
  for (Index layer = 0; layer + 1 < mesh.vertex_count() / sectors; ++layer) {
    const double r = norm(mesh.vertex(layer * sectors)), next = norm(mesh.vertex((layer + 1) * sectors));
    if (next - r < thinnest) {
      thinnest = next - r;
      where = r;
    }
  }
  EXPECT_NEAR(thinnest, 0.001, 5e-5);
  EXPECT_NEAR(where, 0.75, 0.002);
}

TEST(ShearCircleCase, ThinnerLayerResolvedToo) {
  // h-min 1e-5: the layer is 200 times thinner than the default's sampling would need.
  AnalyticMetricSpec spec = shear_circle();
  spec.h_min = 1e-5;
  const Mesh<2> mesh = generate_shear_circle_annulus(0.5, 1.0, spec);
  const Index sectors = mesh.facet_count() / 2;
  double thinnest = 1;
  for (Index layer = 0; layer + 1 < mesh.vertex_count() / sectors; ++layer)
    thinnest = std::min(thinnest, norm(mesh.vertex((layer + 1) * sectors)) - norm(mesh.vertex(layer * sectors)));
  EXPECT_NEAR(thinnest, 1e-5, 1e-6);
}

TEST(ShearCircleCase, ChordsSagBelowTheLayerThickness) {
  // What makes the case meaningful: a tangential edge at r0 dips by its sagitta h_t² / (8 r0),
  // more than the layer is thick — curving it along the circle is worth it.
  const Mesh<2> mesh = generate_shear_circle_annulus(0.5, 1.0, shear_circle());
  const Index sectors = mesh.facet_count() / 2;
  const double chord = norm(mesh.vertex(1) - mesh.vertex(0)) * 0.75 / 0.5;
  EXPECT_GT(chord * chord / (8 * 0.75), 0.001);
  EXPECT_GT(sectors, 40);
}

TEST(ShearCircleCase, RejectsMismatchedParameters) {
  AnalyticMetricSpec spec = shear_circle();
  EXPECT_THROW(generate_shear_circle_annulus(0.8, 1.0, spec), Error);  // r0 = 0.75 outside
  spec.origin = {0.1, 0, 0};
  EXPECT_THROW(generate_shear_circle_annulus(0.5, 1.0, spec), Error);
  spec = shear_circle();
  spec.name = "uniform";
  EXPECT_THROW(generate_shear_circle_annulus(0.5, 1.0, spec), Error);
  spec = shear_circle();
  spec.h_min = 1e-5;
  spec.h_max = 1e-4;
  EXPECT_THROW(generate_shear_circle_annulus(0.5, 1.0, spec), Error);  // 47124 sectors x 5000 layers
  spec = shear_circle();
  spec.h_min = -1;
  EXPECT_THROW(generate_shear_circle_annulus(0.5, 1.0, spec), Error);
}

}  // namespace
}  // namespace hocav
