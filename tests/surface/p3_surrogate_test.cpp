#include "surface/p3_surrogate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "base/error.hpp"
#include "cases/structured.hpp"
#include "surface/analytic_boundary.hpp"
#include "surface_test_meshes.hpp"
#include "surrogate_checks.hpp"

namespace hocav {
namespace {

using testing::circle_polygon;
using testing::expect_no_cracks;
using testing::icosphere;
using testing::max_distance_to_sphere;
using testing::patch_edge_parameters;

template <int D>
Vec<D> unit(const Vec<D>& v) {
  return v * (1 / norm(v));
}

// The boundary facets of a mesh alone, every facet with ref `ref` (no ridge tags).
template <int D>
Mesh<D> facets_only(const Mesh<D>& mesh, int ref) {
  Mesh<D> copy;
  for (const Vec<D>& point : mesh.vertices()) copy.add_vertex(point);
  for (const auto& facet : mesh.facets()) copy.add_facet(facet, ref);
  return copy;
}

// Splits a sphere's facets into ref 1 (centroid below z = 0) and ref 2 (above).
Mesh<3> two_hemispheres(const Mesh<3>& sphere) {
  Mesh<3> mesh;
  for (const Vec3& point : sphere.vertices()) mesh.add_vertex(point);
  for (const auto& facet : sphere.facets()) {
    const double z = sphere.vertex(facet[0])[2] + sphere.vertex(facet[1])[2] + sphere.vertex(facet[2])[2];
    mesh.add_facet(facet, z > 0 ? 2 : 1);
  }
  return mesh;
}

// The surrogate's normal at local vertex i of patch p, from its derivatives there.
template <int D>
Vec<D> patch_normal_at_vertex(const CubicPatch<D>& patch, int i) {
  PatchParameters<D> parameters{};
  if (i > 0) parameters[i - 1] = 1;
  const PatchJet<D> jet = evaluate_jet(patch, parameters);
  if constexpr (D == 2)
    return unit(Vec2{{jet.first[0][1], -jet.first[0][0]}});
  else
    return unit(cross(jet.first[0], jet.first[1]));
}

// Interpolation and G1: every patch passes through its vertices, tangent to its side's normal there.
template <int D>
void expect_interpolating_and_tangent(const Mesh<D>& mesh, const P3Surrogate<D>& surrogate) {
  ASSERT_EQ(surrogate.patch_count(), mesh.facet_count());
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int i = 0; i < D; ++i) {
      PatchParameters<D> parameters{};
      if (i > 0) parameters[i - 1] = 1;
      EXPECT_EQ(evaluate(surrogate.patch(f), parameters), mesh.vertex(mesh.facet(f)[i]));
      const Vec<D> normal = patch_normal_at_vertex(surrogate.patch(f), i);
      const Vec<D>& vertex_normal = surrogate.vertex_normals().at(f, i);
      EXPECT_GT(dot(normal, vertex_normal), 1 - 1e-12) << "facet " << f << " vertex " << i;
    }
}

TEST(SurfaceSurrogate, SphereInterpolatesIsTangentAndHasNoCracks) {
  const Mesh<3> mesh = icosphere(2, 1.0, 0.2);
  for (NormalWeights weights : {NormalWeights::kAngle, NormalWeights::kArea, NormalWeights::kMax}) {
    const P3Surrogate<3> surrogate(mesh, {.normals = {.weights = weights}});
    expect_interpolating_and_tangent(mesh, surrogate);
    expect_no_cracks(mesh, surrogate);
  }
}

// Two refs on one smooth sphere: the equator is a ridge of refs, but the surface does not fold
// there, so the sides merge and the surrogate is that of the single-ref sphere.
TEST(SurfaceSurrogate, SmoothRefBoundaryIsNotARidge) {
  const Mesh<3> sphere = icosphere(2, 1.0, 0.2);
  const Mesh<3> mesh = two_hemispheres(sphere);
  const P3Surrogate<3> surrogate(mesh), single_ref(sphere);
  Index ridge_sides = 0;
  for (const auto& ridges : surrogate.topology().ridges) ridge_sides += ridges[0] + ridges[1] + ridges[2];
  EXPECT_GT(ridge_sides, 0);
  EXPECT_EQ(Index(surrogate.vertex_normals().normals.size()), mesh.vertex_count());
  for (Index f = 0; f < mesh.facet_count(); ++f) EXPECT_EQ(surrogate.patch(f).control, single_ref.patch(f).control);
}

// The largest distance of the midpoints of the rim edges (side facet against a cap) to the circle.
double rim_midpoint_error(const Mesh<3>& mesh, const P3Surrogate<3>& surrogate) {
  double worst = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int side = 0; side < 3; ++side) {
      if (mesh.facet_ref(f) != 1 || mesh.facet_ref(surrogate.topology().neighbors[f][side]) == 1) continue;
      const Vec3 middle = *surrogate.edge_midpoint(mesh.facet(f)[(side + 1) % 3], mesh.facet(f)[(side + 2) % 3]);
      worst = std::max(worst, std::abs(std::hypot(middle[0], middle[1]) - 1));
    }
  return worst;
}

// A crease along a curve: the rims of a closed cylinder (refs 1 side, 2 and 3 caps, at 90°). The
// rim vertices have a normal per side, the rim edges follow the circles (ridge rule: exactly with
// circular-arc tangent lengths, to O(h⁴) with thirds), the caps stay flat and nothing cracks.
TEST(SurfaceSurrogate, CylinderRimsAreCurvedRidges) {
  std::array<double, 2> third_error{};
  for (int refinement = 0; refinement < 2; ++refinement) {
    const Mesh<3> mesh = testing::capped_cylinder(16 << refinement);
    const P3Surrogate<3> surrogate(mesh);
    expect_interpolating_and_tangent(mesh, surrogate);
    expect_no_cracks(mesh, surrogate);
    for (Index f = 0; f < mesh.facet_count(); ++f) {
      if (mesh.facet_ref(f) == 1) continue;
      const double z = mesh.facet_ref(f) == 2 ? 0.0 : 1.0;
      for (const Vec3& point : surrogate.patch(f).control) EXPECT_EQ(point[2], z) << "cap facet " << f;
    }
    EXPECT_LT(rim_midpoint_error(mesh, surrogate), 1e-9);  // exact up to the fitted side normals
    third_error[refinement] = rim_midpoint_error(mesh, P3Surrogate<3>(mesh, {.tangent_length = TangentLength::kProjectedThird}));
  }
  std::printf("cylinder rim edge midpoints with thirds: distance to the circle %.3e (h) %.3e (h/2), order %.2f\n", third_error[0],
              third_error[1], std::log2(third_error[0] / third_error[1]));
  EXPECT_GT(std::log2(third_error[0] / third_error[1]), 3.5);
}

TEST(SurfaceSurrogate, CircleInterpolatesAndIsTangent) {
  const Mesh<2> mesh = circle_polygon(17, 1.0, 0.2);
  expect_interpolating_and_tangent(mesh, P3Surrogate<2>(mesh));
  EXPECT_EQ(P3Surrogate<2>(mesh).vertex_normals().normals.size(), 17u);  // one side per vertex
}

// A planar boundary gives flat patches: the surrogate is the facets, exactly.
template <int D>
double max_distance_to_facets(const Mesh<D>& mesh, const P3Surrogate<D>& surrogate) {
  double worst = 0;
  const int n = 8;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= (D == 3 ? n - i : 0); ++j) {
        PatchParameters<D> parameters{};
        parameters[0] = double(i) / n;
        if constexpr (D == 3) parameters[1] = double(j) / n;
        Vec<D> linear = mesh.vertex(mesh.facet(f)[0]);
        for (int k = 1; k < D; ++k) linear += parameters[k - 1] * (mesh.vertex(mesh.facet(f)[k]) - mesh.vertex(mesh.facet(f)[0]));
        worst = std::max(worst, norm(evaluate(surrogate.patch(f), parameters) - linear));
      }
  return worst;
}

TEST(SurfaceSurrogate, CubeIsItsFacetsAndItsNormalsSplitAtRidges) {
  const Mesh<3> cube = generate_cube(3);
  // Refs and Ridges tag the cube's edges; on a single-ref copy without tags the feature angle does.
  for (const Mesh<3>& mesh : {cube, facets_only(cube, 1)}) {
    const P3Surrogate<3> surrogate(mesh);
    EXPECT_LT(max_distance_to_facets(mesh, surrogate), 1e-15);
    expect_interpolating_and_tangent(mesh, surrogate);
    expect_no_cracks(mesh, surrogate);
    // Sides per vertex: 3 at the cube's corners, 2 along its edges, 1 inside its faces.
    std::vector<std::set<Index>> sides(mesh.vertex_count());
    for (Index f = 0; f < mesh.facet_count(); ++f)
      for (int i = 0; i < 3; ++i) sides[mesh.facet(f)[i]].insert(surrogate.vertex_normals().corner_sides[f][i]);
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
      if (sides[v].empty()) continue;
      int on_faces = 0;
      for (int axis = 0; axis < 3; ++axis) on_faces += mesh.vertex(v)[axis] == 0.0 || mesh.vertex(v)[axis] == 1.0;
      EXPECT_EQ(Index(sides[v].size()), on_faces) << "vertex " << v;
      for (Index side : sides[v]) {
        const Vec3& normal = surrogate.vertex_normals().normals[side];
        EXPECT_NEAR(std::abs(normal[0]) + std::abs(normal[1]) + std::abs(normal[2]), 1.0, 1e-15);  // an axis
      }
    }
    // The ridge edge curves are the straight edges: their midpoints are the straight midpoints.
    EXPECT_EQ(*surrogate.edge_midpoint(0, 1), 0.5 * (mesh.vertex(0) + mesh.vertex(1)));
  }
  // Without a split (feature angle above the cube's 90°, one ref) the normals bend round the edges.
  const Mesh<3> smooth = facets_only(cube, 1);
  EXPECT_GT(max_distance_to_facets(smooth, P3Surrogate<3>(smooth, {.normals = {.feature_angle_degrees = 100}})), 0.01);
}

// Gamma Edges listed in Ridges are ridges of their own: on a single-ref cube whose dihedral angle
// the feature angle does not catch, the tagged edges alone split the normals and keep it flat.
TEST(SurfaceSurrogate, TaggedRidgesSplitTheNormals) {
  const Mesh<3> cube = generate_cube(3);
  Mesh<3> tagged = facets_only(cube, 1);
  for (Index l = 0; l < cube.line_count(); ++l) tagged.add_line(cube.line(l), cube.line_ref(l));
  tagged.ridges() = cube.ridges();
  ASSERT_GT(tagged.ridges().size(), 0u);
  const SurrogateOptions<3> blunt{.normals = {.feature_angle_degrees = 100}};
  const P3Surrogate<3> surrogate(tagged, blunt);
  EXPECT_LT(max_distance_to_facets(tagged, surrogate), 1e-15);
  expect_no_cracks(tagged, surrogate);
  tagged.ridges().clear();
  EXPECT_GT(max_distance_to_facets(tagged, P3Surrogate<3>(tagged, blunt)), 0.01);
}

TEST(SurfaceSurrogate, SquareIsItsSegments) {
  const Mesh<2> square = generate_square(4);
  EXPECT_LT(max_distance_to_facets(square, P3Surrogate<2>(square)), 1e-15);
  const Mesh<2> one_ref = facets_only(square, 1);
  EXPECT_LT(max_distance_to_facets(one_ref, P3Surrogate<2>(one_ref)), 1e-15);
}

// Distance of the surrogate to the sphere at two sizes h and h/2, and the observed order.
struct Convergence {
  double coarse = 0, fine = 0;
  double order() const { return std::log2(coarse / fine); }
};

Convergence sphere_convergence(int coarse_levels, double jitter, const SurrogateOptions<3>& options) {
  Convergence result;
  for (int level : {coarse_levels, coarse_levels + 1}) {
    const Mesh<3> mesh = icosphere(level, 1.0, jitter);
    (level == coarse_levels ? result.coarse : result.fine) = max_distance_to_sphere<3>(P3Surrogate<3>(mesh, options), 1.0, 12);
  }
  return result;
}

template <int D>
AnalyticBoundary<D> unit_sphere() {
  AnalyticBoundary<D> sphere;
  sphere.add(1, AnalyticSurface<D>::sphere({}, 1.0));
  return sphere;
}

// Distance of the surrogate to the sphere, sampled on the patches. An error δ in the vertex normals
// moves an edge midpoint by about h δ / 8: averaged facet normals (fit off) err by O(h²) on the
// regular icosphere but O(h) once its vertices are moved at random by 20% of h, so the surface
// converges at order 3 and 2; the quadric fit keeps O(h²) normals (order 3 or more); Max's weights
// and the exact normals are exact on a sphere whatever the mesh (order 4, the patches' own).
TEST(SurfaceSurrogate, SphereConvergence) {
  const AnalyticBoundary<3> sphere = unit_sphere<3>();
  struct Variant {
    const char* name;
    SurrogateOptions<3> options;
    std::array<double, 2> min_order;  // regular, jittered
  };
  for (const Variant& variant :
       {Variant{"angle", {.normals = {.quadric_fit = false}}, {2.3, 1.4}},
        Variant{"area", {.normals = {.weights = NormalWeights::kArea, .quadric_fit = false}}, {2.3, 1.3}},
        Variant{"max", {.normals = {.weights = NormalWeights::kMax, .quadric_fit = false}}, {3.7, 3.2}}, Variant{"quadric", {}, {3.5, 3.2}},
        Variant{"analytic", {.normals = {.normal_source = &sphere}}, {3.7, 3.2}}})
    for (int jittered : {0, 1}) {
      const Convergence c = sphere_convergence(2, 0.2 * jittered, variant.options);
      std::printf("sphere%s, %-8s normals: max distance %.3e (h) %.3e (h/2), order %.2f\n", jittered ? " jittered" : "", variant.name,
                  c.coarse, c.fine, c.order());
      EXPECT_GT(c.order(), variant.min_order[jittered]) << variant.name << (jittered ? " jittered" : "");
    }
}

// A surface that is no sphere: the ellipsoid x² + (y/0.7)² + (z/0.5)² = 1 (the jittered icosphere
// scaled), distance measured as |F| / |∇F|. The quadric fit keeps its order, Max's weights lose it.
TEST(SurfaceSurrogate, EllipsoidConvergence) {
  const Vec3 axes{{1.0, 0.7, 0.5}};
  auto distance = [&axes](const Vec3& x) {
    double value = -1;
    Vec3 gradient;
    for (int k = 0; k < 3; ++k) {
      value += x[k] * x[k] / (axes[k] * axes[k]);
      gradient[k] = 2 * x[k] / (axes[k] * axes[k]);
    }
    return std::abs(value) / norm(gradient);
  };
  struct Variant {
    const char* name;
    SurrogateOptions<3> options;
    double min_order;
  };
  for (const Variant& variant :
       {Variant{"angle", {.normals = {.quadric_fit = false}}, 1.5},
        Variant{"max", {.normals = {.weights = NormalWeights::kMax, .quadric_fit = false}}, 1.5}, Variant{"quadric", {}, 2.8}}) {
    std::array<double, 2> error{};
    for (int level : {3, 4}) {
      Mesh<3> mesh = icosphere(level, 1.0, 0.2);
      for (Index v = 0; v < mesh.vertex_count(); ++v)
        for (int k = 0; k < 3; ++k) mesh.vertex(v)[k] *= axes[k];
      const P3Surrogate<3> surrogate(mesh, variant.options);
      for (Index p = 0; p < surrogate.patch_count(); ++p)
        for (int i = 0; i <= 6; ++i)
          for (int j = 0; j <= 6 - i; ++j)
            error[level - 3] = std::max(error[level - 3], distance(evaluate(surrogate.patch(p), {i / 6.0, j / 6.0})));
    }
    const double order = std::log2(error[0] / error[1]);
    std::printf("jittered ellipsoid, %-8s normals: max distance %.3e (h) %.3e (h/2), order %.2f\n", variant.name, error[0], error[1],
                order);
    EXPECT_GT(order, variant.min_order) << variant.name;
  }
}

TEST(SurfaceSurrogate, CircleConvergence) {
  const AnalyticBoundary<2> circle = unit_sphere<2>();
  struct Variant {
    const char* name;
    SurrogateOptions<2> options;
    double min_order;
  };
  for (const Variant& variant : {Variant{"equal", {.normals = {.quadric_fit = false}}, 1.3}, Variant{"quadric", {}, 2.7},
                                 Variant{"analytic", {.normals = {.normal_source = &circle}}, 5}}) {
    const double coarse = max_distance_to_sphere<2>(P3Surrogate<2>(circle_polygon(16, 1.0, 0.2), variant.options), 1.0, 50);
    const double fine = max_distance_to_sphere<2>(P3Surrogate<2>(circle_polygon(32, 1.0, 0.2), variant.options), 1.0, 50);
    std::printf("jittered circle, %-8s normals: max distance %.3e (h) %.3e (h/2), order %.2f\n", variant.name, coarse, fine,
                std::log2(coarse / fine));
    EXPECT_GT(std::log2(coarse / fine), variant.min_order) << variant.name;
  }
}

}  // namespace
}  // namespace hocav
