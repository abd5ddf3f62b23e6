// Issue 5's hard case for the P2 cavity operator: the boundary-layer cubed-sphere shell at a coarse
// tangential size, curved in its implied metric with the P3 surrogate of its boundary.
//
// With n = 3 cells per cube side the inner sphere's edges are chords of about r_in π/6 = 0.26; they
// sag below the sphere by about 0.26² / (8 r_in) = 0.017, while the first layer is r_in (π/6) / 50 =
// 0.0052 thick. Moving an inner boundary edge's node onto the sphere would push it through the first
// layer: the operator has to pull nodes back (corrections) to keep every element above the floor.
// The isotropic shell of the same tetrahedron count (cells as thick as they are wide) needs no
// correction.
#include <gtest/gtest.h>

#include <optional>

#include <cmath>

#include "adapt/adaptation_driver.hpp"
#include "adapt/proposal_node_source.hpp"
#include "adapt/reinsertion_curving.hpp"
#include "bezier/jacobian_bounds.hpp"
#include "cases/cubed_sphere_shell.hpp"
#include "mesh/consistency.hpp"
#include "metric/implied_metric.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

struct CurvedShell {
  Mesh<3> mesh;
  ReinsertionResult result;
};

CurvedShell curve_in_implied_metric(const ShellLayering& layering, double target_tets) {
  CurvedShell shell;
  shell.mesh = generate_cubed_sphere_shell(layering, target_tets);
  const MetricField<3> field(shell.mesh, implied_metric_at_vertices(shell.mesh));
  const P3Surrogate<3> surrogate(shell.mesh);
  BoundaryProposals<3> proposals(shell.mesh, surrogate);
  ProposalNodeSource<3> nodes(proposals);
  shell.result = curve_by_reinsertion<3>(shell.mesh, field, &nodes);
  return shell;
}

// How far each boundary edge of a sphere moved its node from the chord's midpoint toward the sphere,
// as a fraction of the midpoint's distance to it (1: on the sphere, 0: straight).
std::vector<double> recovered_sag(const Mesh<3>& mesh, int ref, double radius) {
  std::vector<double> fractions;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_ref(f) != ref) continue;
    const auto& t = mesh.facet(f);
    for (int i = 0; i < 3; ++i) {
      const Index a = t[i], b = t[(i + 1) % 3];
      if (a > b) continue;  // each edge once (its two facets list it in opposite directions)
      const double straight = radius - norm(0.5 * (mesh.vertex(a) + mesh.vertex(b)));
      fractions.push_back(1 - (radius - norm(mesh.edge_node(mesh.find_edge(a, b)))) / straight);
    }
  }
  return fractions;
}

TEST(BoundaryLayerCurving, ThinLayersUnderACoarseCurvedWallNeedCorrectionsAndEndValid) {
  // The registry's default cubed-shell-bl-inner at 5000 tetrahedra: n = 3, 17 layers.
  const CurvedShell shell = curve_in_implied_metric({0.5, 1.0, LayerWalls::kInner}, 5000);
  ASSERT_EQ(shell.mesh.facet_count(), 2 * 12 * 3 * 3);
  const P2CavityCounters& counters = shell.result.counters;
  EXPECT_GT(counters.corrections, 0);
  EXPECT_EQ(counters.accepted + counters.rejected_topology + counters.rejected_curving, counters.cavities);
  EXPECT_GE(counters.accepted, counters.cavities * 95 / 100);
  EXPECT_GT(counters.boundary_nodes_applied, 0);

  ConsistencyOptions consistency;
  consistency.require_positive_orientation = false;  // a valid P2 element may be an inverted P1 one
  consistency.require_boundary_facets = true;
  EXPECT_EQ(check_consistency(shell.mesh, consistency), std::vector<std::string>{});
  // Every element certified above the floor by the Bézier test, as the operator promised.
  const double floor = ReinsertionOptions{}.cavity.jacobian_floor;
  for (Index k = 0; k < shell.mesh.element_count(); ++k)
    ASSERT_TRUE(certify_min_normalized_jacobian_above(gather_p2_element(shell.mesh, k), floor)) << "element " << k;

  // The outer sphere, under isotropic cells, takes its curvature fully; the inner one, under the
  // thin layer, partly: its nodes moved toward the sphere but not all the way.
  auto mean = [](const std::vector<double>& values) {
    double sum = 0;
    for (double v : values) sum += v;
    return sum / static_cast<double>(values.size());
  };
  const auto outer = recovered_sag(shell.mesh, 2, 1.0), inner = recovered_sag(shell.mesh, 1, 0.5);
  EXPECT_NEAR(mean(outer), 1, 0.1);
  for (double fraction : inner) {
    EXPECT_GE(fraction, -1e-9);
    EXPECT_LE(fraction, 1.1);
  }
  // (Measured: 5.5% of the sag on average, at most 20%; the first layer's edges, straight in the
  // implied metric of the straight mesh, hold the wall's nodes back.)
  EXPECT_GT(mean(inner), 0.01);
  EXPECT_LT(mean(inner), 0.9);
}

TEST(BoundaryLayerCurving, TheIsotropicShellOfTheSameSizeNeedsNoCorrection) {
  const CurvedShell shell = curve_in_implied_metric(ShellLayering{}, 5000);
  EXPECT_GT(shell.result.counters.cavities, 0);
  EXPECT_GT(shell.result.counters.boundary_nodes_applied, 0);
  EXPECT_EQ(shell.result.counters.corrections, 0);
  EXPECT_EQ(shell.result.counters.accepted, shell.result.counters.cavities);
}

// The largest distance from the sphere of the wall's P2 nodes (ref 1, radius 0.5), and of the
// input surrogate's points for them: issue 13's measure (bench/sphere_wall_error.cpp).
std::array<double, 2> wall_errors(const Mesh<3>& mesh, const Mesh<3>& input) {
  const P3Surrogate<3> surrogate(input);
  std::array<double, 2> largest{0, 0};
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_ref(f) != 1) continue;
    for (int i = 0; i < 3; ++i) {
      const Vec3 node = mesh.edge_node(mesh.find_edge(mesh.facet(f)[i], mesh.facet(f)[(i + 1) % 3]));
      largest[0] = std::max(largest[0], std::abs(norm(node) - 0.5));
      largest[1] = std::max(largest[1], std::abs(norm(surrogate.project(node, {.ref = 1}).point) - 0.5));
    }
  }
  return largest;
}

// The shell adapted with its wall's sag bounded by `relative` times the size across it
// (--hausd-relative; the curved output's default when none), then curved (and, with `curved`, curved
// passes after: --curved).
AdaptedMesh<3> adapt_bounded_wall(Mesh<3>& mesh, const Mesh<3>& input, std::optional<double> relative, bool curved) {
  AdaptationJob<3> job;
  job.hausd_relative = relative;
  job.threads = 2;
  job.curving.emplace();
  job.curving->threads = 2;
  job.curved = curved;
  job.geometry = [](const Mesh<3>& m) { return std::unique_ptr<BoundaryGeometry<3>>(std::make_unique<P3Surrogate<3>>(m)); };
  return run_adaptation_job(mesh, implied_metric_at_vertices(input), job, "the shell");
}

// The wall adapted within its first layer keeps within it, and the curving then puts it on the
// geometry, the layers bent with it where they are thin: every node within twice the surrogate's
// own error (measured 0.98 times).
TEST(BoundaryLayerCurving, AWallAdaptedWithinItsFirstLayerCurvesOntoTheGeometry) {
  const Mesh<3> input = generate_cubed_sphere_shell({0.5, 1.0, LayerWalls::kInner}, 5000);
  Mesh<3> mesh = input;
  const AdaptedMesh<3> adapted = adapt_bounded_wall(mesh, input, 0.5, false);
  EXPECT_GT(adapted.report.hausdorff_bounded_vertices, 0);
  const auto [node, surrogate] = wall_errors(mesh, input);
  EXPECT_LT(node, 2 * surrogate) << node << " " << surrogate;
  EXPECT_GE(adapted.report.curving->normalized_jacobian.min, CurvingOptions{}.jacobian_floor);
}

// At the default bound (the sag within the size across), with curved passes, which split, collapse
// and flip on the wall too (their new vertices and boundary nodes on the geometry): the wall within
// twice the surrogate's error, every element certified (issue 13's target; measured 1.61 times, 129
// boundary operations).
TEST(BoundaryLayerCurving, CurvedPassesKeepTheWallOnTheGeometryAtTheDefaultBound) {
  const Mesh<3> input = generate_cubed_sphere_shell({0.5, 1.0, LayerWalls::kInner}, 5000);
  Mesh<3> mesh = input;
  const AdaptedMesh<3> adapted = adapt_bounded_wall(mesh, input, std::nullopt, true);
  EXPECT_GT(adapted.report.hausdorff_bounded_vertices, 0);
  ASSERT_TRUE(adapted.report.curved_passes);
  Index on_boundary = 0;
  for (const CurvedPass& pass : adapted.report.curved_passes->passes)
    on_boundary += pass.collapses.boundary_done + pass.splits.boundary_done + pass.moves.boundary_done;
  EXPECT_GT(on_boundary, 0);
  EXPECT_TRUE(adapted.report.curved_passes->converged);
  const auto [node, surrogate] = wall_errors(mesh, input);
  EXPECT_LT(node, 2 * surrogate) << node << " " << surrogate;
  EXPECT_GE(adapted.report.curving->normalized_jacobian.min, CurvingOptions{}.jacobian_floor);
  EXPECT_EQ(adapted.report.curving->normalized_jacobian.invalid_count, 0);
}

}  // namespace
}  // namespace hocav
