// The machined part (docs/cases.md) and what issue 17 asks of its curving: every boundary mid node
// on the CAD, ridge nodes on the curve their two surfaces share, the edges of elements with only
// boundary vertices curved too, the surrogate's ridge curves shared by both patches, and the
// Jacobian floor stopping a node where the thin wall leaves no room (docs/curving.md).
#include "cases/machined_part.hpp"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "adapt/curving_run.hpp"
#include "bezier/mesh_quality.hpp"
#include "gmsh_requirement.hpp"
#include "mesh/boundary_vertices.hpp"
#include "mesh/consistency.hpp"
#include "mesh/measure.hpp"
#include "metric/analytic_metric.hpp"
#include "surface/cad_boundary_gmsh.hpp"
#include "surface/cubic_patch.hpp"
#include "surface/surrogate_checks.hpp"

namespace hocav {
namespace {

// Coarse: the 0.03 walls are half an element thick, and the test stays fast (about 5,000 tetrahedra).
const MachinedPartParameters kCoarse{.size = 0.06, .wall = 0.03};
// How far below P1's largest boundary error the surrogate's must be on the part at h = 0.03 and
// 0.02: issue 17's target (measured 11.8 and 15.9, docs/surface.md).
constexpr double kSurrogateGain = 10;

double bounding_box_diagonal(const Mesh<3>& mesh) {
  Vec3 low = mesh.vertex(0), high = mesh.vertex(0);
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    for (int i = 0; i < 3; ++i) {
      low[i] = std::min(low[i], mesh.vertex(v)[i]);
      high[i] = std::max(high[i], mesh.vertex(v)[i]);
    }
  return norm(high - low);
}

// The elements whose vertices are all on the boundary: no volume vertex's ball reaches them.
std::vector<Index> boundary_only_elements(const Mesh<3>& mesh) {
  const std::vector<bool> on_boundary = boundary_vertex_flags(mesh);
  std::vector<Index> elements;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    bool all = true;
    for (Index v : mesh.element(k)) all = all && on_boundary[v];
    if (all) elements.push_back(k);
  }
  return elements;
}

TEST(MachinedPart, IsAValidDeterministicMeshWithItsFeatures) {
  HOCAV_SKIP_WITHOUT_GMSH();
  const Mesh<3> mesh = generate_machined_part(kCoarse);
  EXPECT_EQ(check_consistency(mesh), std::vector<std::string>{});
  std::set<int> refs;
  for (Index f = 0; f < mesh.facet_count(); ++f) refs.insert(mesh.facet_ref(f));
  EXPECT_EQ(refs.size(), 22u);  // the CAD surfaces
  EXPECT_GT(boundary_only_elements(mesh).size(), 100u);
  // Below the block's volume by the hole, the pockets, the slant and the rounded corners.
  EXPECT_GT(total_measure(mesh), 0.15);
  EXPECT_LT(total_measure(mesh), 0.2);
  const Mesh<3> again = generate_machined_part(kCoarse);
  ASSERT_EQ(again.vertex_count(), mesh.vertex_count());
  for (Index v = 0; v < mesh.vertex_count(); ++v) EXPECT_EQ(again.vertex(v), mesh.vertex(v));
  EXPECT_THROW(generate_machined_part({.size = 0}), Error);
  EXPECT_THROW(generate_machined_part({.size = 0.06, .wall = 0.2}), Error);
  EXPECT_THROW(generate_machined_part({.size = 0.06, .wall = 0}), Error);
}

TEST(MachinedPart, CurvedWithTheCadEveryBoundaryNodeOnItOrHeldByTheFloor) {
  HOCAV_SKIP_WITHOUT_GMSH();
  Mesh<3> mesh = generate_machined_part(kCoarse);
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "hocav_part.step").string();
  write_machined_part_cad(kCoarse, path);
  const CadBoundary<3> cad(path, mesh);
  const double model_size = bounding_box_diagonal(mesh);
  const std::vector<Index> boundary_only = boundary_only_elements(mesh);
  AnalyticMetricSpec spec;
  spec.h = kCoarse.size;
  const MetricField<3> field(mesh, analytic_metric_at_vertices(spec, mesh));
  const CurvingRun run = curve_with_boundary<3>(mesh, field, &cad, {});
  std::filesystem::remove(path);

  const ProposalCompletion& completion = run.report.boundary_completion;
  EXPECT_GT(completion.placed, 0);
  EXPECT_EQ(run.report.boundary_proposals_left, completion.pulled_back + completion.blocked);
  // The thin wall: some nodes cannot reach the CAD without an element below the floor...
  EXPECT_GT(completion.pulled_back + completion.blocked, 0);
  EXPECT_LT(completion.largest_gap, 0.2 * kCoarse.size);
  // ...and every element is certified above it.
  EXPECT_GT(run.report.normalized_jacobian.min, 0.01);

  // Every boundary mid node lies on the surfaces of both its facets (a ridge node on the curve they
  // share) within 1e-9 of the model's size, except the nodes the floor held back.
  std::map<std::uint64_t, std::set<int>> refs_of_edge;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (const auto& ends : kPatchEdges<3>)
      refs_of_edge[Mesh<3>::edge_key(mesh.facet(f)[ends[0]], mesh.facet(f)[ends[1]])].insert(mesh.facet_ref(f));
  Index ridge_edges = 0, off_cad = 0, ridge_off_cad = 0;
  std::set<std::uint64_t> off_cad_keys;
  for (const auto& [key, refs] : refs_of_edge) {
    const Index a = static_cast<Index>(key >> 32), b = static_cast<Index>(key & 0xffffffffu);
    const Vec3 node = mesh.edge_node(mesh.find_edge(a, b));
    double distance = 0;
    for (int ref : refs) distance = std::max(distance, cad.project(node, {.ref = ref}).distance);
    const bool off = distance > 1e-9 * model_size;
    off_cad += off;
    if (off) off_cad_keys.insert(key);
    if (refs.size() > 1) {
      ++ridge_edges;
      ridge_off_cad += off;
    }
  }
  EXPECT_EQ(off_cad, run.report.boundary_proposals_left);
  EXPECT_GT(ridge_edges, 200);
  EXPECT_LE(ridge_off_cad, off_cad);
  // The boundary-only elements' boundary edges were reached: curved where their surface curves.
  Index curved_boundary_only = 0;
  for (Index k : boundary_only)
    for (int e = 0; e < 6; ++e) {
      const Index a = mesh.element(k)[edge_vertices<3>(e)[0]], b = mesh.element(k)[edge_vertices<3>(e)[1]];
      if (!refs_of_edge.contains(Mesh<3>::edge_key(a, b)) || off_cad_keys.contains(Mesh<3>::edge_key(a, b))) continue;
      curved_boundary_only += norm(mesh.edge_node(mesh.find_edge(a, b)) - 0.5 * (mesh.vertex(a) + mesh.vertex(b))) > 1e-6;
    }
  EXPECT_GT(curved_boundary_only, 100);
}

// With a 0.01 wall OpenCASCADE stores the curves where two floor fillets meet as B-splines 1.9e-8
// from the fillets (more than 1e-9 of the model's size): the CAD's intersection goes on from the
// curve onto both surfaces (docs/surface.md, CAD backend).
TEST(MachinedPart, CadIntersectionOfTwoFilletsIsOnBothSurfaces) {
  HOCAV_SKIP_WITHOUT_GMSH();
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "hocav_part_thin.step").string();
  write_machined_part_cad({.size = 0.06, .wall = 0.01}, path);
  const CadBoundary<3> cad(path);  // refs are the surface tags
  std::filesystem::remove(path);
  const double tolerance = 1e-9 * std::hypot(1.0, 0.6, 0.4);  // the block's diagonal
  Index samples = 0, curve_points_off = 0;
  gmsh::vectorpair curves;
  gmsh::model::getEntities(curves, 1);
  for (const auto& curve : curves) {
    std::vector<int> surfaces, points;
    gmsh::model::getAdjacencies(1, curve.second, surfaces, points);
    std::string curve_type, type_a, type_b;
    gmsh::model::getType(1, curve.second, curve_type);
    if (surfaces.size() != 2 || curve_type != "BSpline") continue;
    gmsh::model::getType(2, surfaces[0], type_a);
    gmsh::model::getType(2, surfaces[1], type_b);
    if (type_a != "Cylinder" || type_b != "Cylinder") continue;
    std::vector<double> low, high, xyz;
    gmsh::model::getParametrizationBounds(1, curve.second, low, high);
    for (int k = 1; k < 8; ++k) {
      gmsh::model::getValue(1, curve.second, {low[0] + (high[0] - low[0]) * k / 8}, xyz);
      const Vec3 on_curve{{xyz[0], xyz[1], xyz[2]}};
      const double curve_gap = std::max(cad.project(on_curve, {.ref = surfaces[0]}).distance,
                                        cad.project(on_curve, {.ref = surfaces[1]}).distance);
      curve_points_off += curve_gap > tolerance;
      const Vec3 query = on_curve + Vec3{{1e-3, -2e-3, 1e-3}};
      const Vec3 node = cad.project_on_intersection(query, surfaces[0], surfaces[1]);
      EXPECT_LE(norm(node - query), norm(on_curve - query) + tolerance);  // the closest point of the curve
      EXPECT_LT(cad.project(node, {.ref = surfaces[0]}).distance, tolerance);
      EXPECT_LT(cad.project(node, {.ref = surfaces[1]}).distance, tolerance);
      ++samples;
    }
  }
  EXPECT_EQ(samples, 28);  // four fillet-fillet curves
  EXPECT_GT(curve_points_off, 0);
}

// The largest distance from the CAD surfaces of the refs around each boundary edge (both, for a
// ridge edge) of its straight midpoint and of the surrogate's edge-curve midpoint.
// The largest distances to the CAD of a set of edges' straight and surrogate midpoints.
struct LargestErrors {
  double straight = 0, surrogate = 0;
  double gain() const { return straight / surrogate; }
};

struct EdgeErrors {
  LargestErrors all, ridges;  // ridges: the edges between two refs
};

EdgeErrors largest_edge_errors(const Mesh<3>& mesh, const CadBoundary<3>& cad, const P3Surrogate<3>& surrogate) {
  std::map<std::uint64_t, std::set<int>> refs_of_edge;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (const auto& ends : kPatchEdges<3>)
      refs_of_edge[Mesh<3>::edge_key(mesh.facet(f)[ends[0]], mesh.facet(f)[ends[1]])].insert(mesh.facet_ref(f));
  EdgeErrors largest;
  for (const auto& [key, refs] : refs_of_edge) {
    const Index a = static_cast<Index>(key >> 32), b = static_cast<Index>(key & 0xffffffffu);
    const Vec3 straight = 0.5 * (mesh.vertex(a) + mesh.vertex(b)), curved = *surrogate.edge_midpoint(a, b);
    for (int ref : refs)
      for (LargestErrors* errors : {&largest.all, refs.size() > 1 ? &largest.ridges : nullptr})
        if (errors) {
          errors->straight = std::max(errors->straight, cad.project(straight, {.ref = ref}).distance);
          errors->surrogate = std::max(errors->surrogate, cad.project(curved, {.ref = ref}).distance);
        }
  }
  return largest;
}

// The part of docs/benchmarks.md (h = 0.03, its floor fillets one or two edges wide) and the same
// part finer (h = 0.02, where a vertex on the mitre of two floor fillets, next to the floor, took a
// quadric fitted across the fillet-floor junction: 6.3x): the surrogate's mid nodes, measured against
// the CAD, and the figures docs/surface.md reports. The ridges alone too: at h = 0.03 they were 5.0x
// while the ellipse a slanted face cuts from a rounded corner left its listed corner along its
// one-sided circle, 16° off the straight edge it continues.
TEST(MachinedPart, SurrogateMidNodesAreWellBelowTheStraightOnesAtTwoSizes) {
  HOCAV_SKIP_WITHOUT_GMSH();
  for (const double size : {0.03, 0.02}) {
    const MachinedPartParameters part{.size = size, .wall = 0.03};
    const Mesh<3> mesh = generate_machined_part(part);
    EXPECT_GT(mesh.corners().size(), 20u);  // the CAD points where three surfaces meet
    const std::string path = (std::filesystem::path(::testing::TempDir()) / "hocav_part_fine.step").string();
    write_machined_part_cad(part, path);
    const CadBoundary<3> cad(path, mesh);
    std::filesystem::remove(path);
    const EdgeErrors largest = largest_edge_errors(mesh, cad, P3Surrogate<3>(mesh));
    std::printf("machined part h = %g: largest mid-node error P1 %.3e, surrogate %.3e (%.1fx); ridges %.1fx\n", size, largest.all.straight,
                largest.all.surrogate, largest.all.gain(), largest.ridges.gain());
    EXPECT_GT(largest.all.gain(), kSurrogateGain) << "h = " << size;
    EXPECT_GT(largest.ridges.gain(), kSurrogateGain) << "ridges, h = " << size;
  }
}

TEST(MachinedPart, SurrogateRidgeCurvesAreSharedBitForBitByBothPatches) {
  HOCAV_SKIP_WITHOUT_GMSH();
  const Mesh<3> mesh = generate_machined_part(kCoarse);
  const P3Surrogate<3> surrogate(mesh);
  Index ridge_sides = 0;
  for (const auto& ridges : surrogate.topology().ridges) ridge_sides += ridges[0] + ridges[1] + ridges[2];
  EXPECT_GT(ridge_sides, 400);  // both facets' sides of every ridge edge
  testing::expect_no_cracks(mesh, surrogate);
}

}  // namespace
}  // namespace hocav
