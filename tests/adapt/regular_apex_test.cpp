// The smoothing's repair target (src/adapt/regular_apex.hpp): the apex that makes an element regular
// in an isotropic metric, and in any metric the point on the face's normal at the regular altitude.
#include "adapt/regular_apex.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace hocav {
namespace {

// A regular simplex of edge `edge`, its first vertex the apex over the others.
template <int D>
std::array<Vec<D>, D + 1> regular_simplex(double edge) {
  std::array<Vec<D>, D + 1> simplex;
  if constexpr (D == 2)
    simplex = {Vec2{{0.5, std::sqrt(3.0) / 2}}, Vec2{{0, 0}}, Vec2{{1, 0}}};
  else
    simplex = {Vec3{{0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3)}}, Vec3{{0, 0, 0}}, Vec3{{1, 0, 0}}, Vec3{{0.5, std::sqrt(3.0) / 2, 0}}};
  for (Vec<D>& p : simplex) p = edge * p + Vec<D>{{0.3, -0.2}};
  return simplex;
}

template <int D>
std::array<Vec<D>, D> face_of(const std::array<Vec<D>, D + 1>& simplex) {
  std::array<Vec<D>, D> face;
  for (int i = 0; i < D; ++i) face[i] = simplex[i + 1];
  return face;
}

template <int D>
void expect_near(const Vec<D>& x, const Vec<D>& y) {
  for (int i = 0; i < D; ++i) EXPECT_NEAR(x[i], y[i], 1e-12);
}

// In the isotropic metric of size h, the apex of the regular simplex of edge h, from either side.
template <int D>
void expect_regular_apex_isotropic() {
  const double h = 0.05;
  const std::array<Vec<D>, D + 1> simplex = regular_simplex<D>(h);
  const std::array<Vec<D>, D> face = face_of<D>(simplex);
  SymMat<D> metric;
  for (int i = 0; i < D; ++i) metric(i, i) = 1 / (h * h);
  const Vec<D> near_face = 0.99 * face[0] + 0.01 * simplex[0];  // a vertex a hair from the face
  expect_near<D>(regular_apex<D>(face, near_face, metric), simplex[0]);
  Vec<D> centroid{};
  for (const Vec<D>& p : face) centroid = centroid + (1.0 / D) * p;
  expect_near<D>(regular_apex<D>(face, 2.0 * centroid - near_face, metric), 2.0 * centroid - simplex[0]);  // the mirror
}

TEST(RegularApex, IsTheRegularSimplexsApexInAnIsotropicMetric2D) { expect_regular_apex_isotropic<2>(); }
TEST(RegularApex, IsTheRegularSimplexsApexInAnIsotropicMetric3D) { expect_regular_apex_isotropic<3>(); }

// In an anisotropic metric: on the face's normal through its centroid, at the regular altitude of
// the face's mean edge length, both measured in the metric.
TEST(RegularApex, LiesOnTheFacesNormalAtTheRegularAltitudeInTheMetric3D) {
  const std::array<Vec3, 3> face{Vec3{{0, 0, 0}}, Vec3{{1, 0.2, 0.1}}, Vec3{{0.3, 0.9, -0.2}}};
  SymMat<3> metric;
  metric(0, 0) = 4, metric(1, 1) = 100, metric(2, 2) = 1e4, metric(0, 1) = 3, metric(1, 2) = -20;
  const Vec3 centroid = (1.0 / 3) * (face[0] + face[1] + face[2]);
  const Vec3 normal = cross(face[1] - face[0], face[2] - face[0]);
  const Vec3 apex = regular_apex<3>(face, centroid + 1e-3 * normal, metric);
  const Vec3 offset = apex - centroid;
  EXPECT_NEAR(norm(cross(offset, normal)), 0, 1e-12 * norm(offset) * norm(normal));
  EXPECT_GT(dot(offset, normal), 0);
  double mean_length = 0;
  for (int i = 0; i < 3; ++i) mean_length += std::sqrt(quadratic_form(metric, face[i] - face[(i + 1) % 3])) / 3;
  EXPECT_NEAR(std::sqrt(quadratic_form(metric, offset)), std::sqrt(2.0 / 3) * mean_length, 1e-12 * mean_length);
}

}  // namespace
}  // namespace hocav
