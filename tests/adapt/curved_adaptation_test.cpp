// `hocav adapt --curved` end to end (the job of the command): the curved passes keep the mesh
// consistent and certified above the Jacobian floor, fix edges by their curved length, and leave
// no more edges outside the unit range than adapt-then-curve; the output does not depend on the
// thread count.
#include "adapt/curved_adaptation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../mesh/inner_facet_meshes.hpp"
#include "adapt/adaptation_driver.hpp"
#include "adapt_test_support.hpp"
#include "bezier/mesh_quality.hpp"

namespace hocav {
namespace {

// The unit square or cube adapted to a shear layer around the origin (a curved feature the
// P1 loop's straight edges cross), then (order 2) curved; with `curved`, curved passes after.
template <int D>
struct AdaptedCase {
  Mesh<D> mesh;
  AdaptedMesh<D> adapted;
  AdaptedCase(bool curved, int threads, int order = 2) : AdaptedCase(adapt_test::unit_mesh<D>(D == 2 ? 8 : 4), curved, threads, order) {}
  AdaptedCase(Mesh<D> start, bool curved, int threads, int order = 2) : mesh(std::move(start)) {
    AdaptationJob<D> job;
    job.analytic.emplace();
    job.analytic->name = D == 2 ? "shear-circle" : "shear-sphere";
    job.analytic->radius = 0.6;
    job.analytic->width = 0.05;
    job.analytic->h_min = D == 2 ? 0.02 : 0.03;
    job.analytic->h_max = D == 2 ? 0.1 : 0.2;
    job.threads = threads;
    if (order == 2) job.curving.emplace();
    if (order == 2) job.curving->threads = threads;
    job.curved = curved;
    job.geometry = [](const Mesh<D>&) { return std::unique_ptr<BoundaryGeometry<D>>(); };
    adapted = run_adaptation_job(mesh, {}, job, "the unit mesh");
  }
};

template <int D>
void expect_certified(const Mesh<D>& mesh, double floor) {
  const auto summary = summarize_jacobian_quality(mesh_jacobian_quality(mesh, kReportedRefinement));
  EXPECT_EQ(summary.min_normalized_jacobian.invalid_count, 0);
  EXPECT_GE(summary.min_normalized_jacobian.min, floor);
}

template <int D>
void check_curved_loop() {
  AdaptedCase<D> plain(false, 1), curved(true, 1);
  const AdaptationReport& report = curved.adapted.report;
  ASSERT_TRUE(report.curved_passes);
  ASSERT_FALSE(report.curved_passes->passes.empty());
  const CurvedPass& first = report.curved_passes->passes.front();
  // Work to do after adapt-then-curve: in 3D, since the twelfth session's swap bars, only swaps and
  // moves (its short curved edges are on the boundary or too long to collapse).
  EXPECT_GT(first.splits.done + first.collapses.done + first.swaps.done + first.moves.done, 0)
      << "the curved passes changed nothing after adapt-then-curve";
  adapt_test::expect_closed_and_consistent(curved.mesh);
  EXPECT_EQ(curved.mesh.order(), 2);
  expect_certified(curved.mesh, CurvingOptions{}.jacobian_floor);
  // The report is measured after the curved passes.
  EXPECT_EQ(report.curving->elements, curved.mesh.element_count());
  EXPECT_EQ(report.output_elements, curved.mesh.element_count());
  const CurvedMeasures measured = measure_curved(curved.mesh, *curved.adapted.field);
  EXPECT_EQ(report.curved_measures->unit_share, measured.unit_share);
  // On three threads: the same figures, bit for bit.
  const CurvedMeasures threaded = measure_curved(curved.mesh, *curved.adapted.field, 3);
  EXPECT_EQ(threaded.edge_count, measured.edge_count);
  EXPECT_EQ(threaded.length_min, measured.length_min);
  EXPECT_EQ(threaded.length_mean, measured.length_mean);
  EXPECT_EQ(threaded.length_max, measured.length_max);
  EXPECT_EQ(threaded.unit_share, measured.unit_share);
  EXPECT_EQ(threaded.quality_min, measured.quality_min);
  EXPECT_EQ(threaded.quality_mean, measured.quality_mean);
  // Every edge skipped: the elements alone; the two merged give the whole again (a distributed
  // mesh's parts, curving_in_parts.hpp).
  const CurvedMeasures elements_only = measure_curved(curved.mesh, *curved.adapted.field, 1,
                                                      std::vector<char>(static_cast<std::size_t>(curved.mesh.edge_count()), 1));
  EXPECT_EQ(elements_only.edge_count, 0);
  EXPECT_EQ(elements_only.element_count, curved.mesh.element_count());
  CurvedMeasures edges_only = measured;
  edges_only.element_count = 0;
  edges_only.quality_min = INFINITY;
  const CurvedMeasures merged = merge_curved_measures(elements_only, edges_only);
  EXPECT_EQ(merged.edge_count, measured.edge_count);
  EXPECT_EQ(merged.length_min, measured.length_min);
  EXPECT_EQ(merged.length_max, measured.length_max);
  EXPECT_DOUBLE_EQ(merged.length_mean, measured.length_mean);
  EXPECT_DOUBLE_EQ(merged.unit_share, measured.unit_share);
  EXPECT_EQ(merged.quality_min, measured.quality_min);
  EXPECT_DOUBLE_EQ(merged.quality_mean, measured.quality_mean);
  EXPECT_GE(measured.unit_share, plain.adapted.report.curved_measures->unit_share);
  // No operation makes an element worse than the worst it replaces or the mesh's worst.
  EXPECT_GE(measured.quality_min, plain.adapted.report.curved_measures->quality_min);
  EXPECT_FALSE(plain.adapted.report.curved_passes);
}

TEST(CurvedAdaptation, LoopKeepsTheMeshCertifiedAndUnitInCurvedLength2D) { check_curved_loop<2>(); }
TEST(CurvedAdaptation, LoopKeepsTheMeshCertifiedAndUnitInCurvedLength3D) { check_curved_loop<3>(); }

// Four element refs by quadrant through the whole job with the curved passes: every element keeps
// its quadrant's ref and is certified, and the interfaces' P2 nodes stay on their planes.
template <int D>
void expect_interfaces_kept_curved() {
  const Mesh<D> start = mesh_test::four_refs_by_quadrant<D>(D == 2 ? 8 : 4);
  AdaptedCase<D> quadrants(start, true, 1);
  const Mesh<D>& mesh = quadrants.mesh;
  ASSERT_TRUE(quadrants.adapted.report.curved_passes);
  EXPECT_GT(mesh.element_count(), 2 * start.element_count()) << "the shear layer refines across the interfaces";
  adapt_test::expect_closed_and_consistent(mesh);
  expect_certified(mesh, CurvingOptions{}.jacobian_floor);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    Vec<D> centroid{};
    for (Index v : mesh.element(k)) centroid += mesh.vertex(v) * (1.0 / (D + 1));
    EXPECT_EQ(mesh.element_ref(k), 1 + (centroid[0] > 0.5) + 2 * (centroid[1] > 0.5)) << "element " << k;
  }
  Index interface_edges = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_ref(f) != 9 && mesh.facet_ref(f) != 10) continue;
    const int axis = mesh.facet_ref(f) == 9 ? 0 : 1;
    const auto& facet = mesh.facet(f);
    for (int i = 0; i < D; ++i, ++interface_edges) {
      const Index e = mesh.find_edge(facet[i], facet[(i + 1) % D]);
      ASSERT_NE(e, kNoIndex);
      EXPECT_NEAR(mesh.edge_node(e)[axis], 0.5, 1e-12) << "facet " << f;
    }
  }
  EXPECT_GT(interface_edges, 0);
}

TEST(CurvedAdaptation, InterfacesKeepTheirSidesAndPlanes2D) { expect_interfaces_kept_curved<2>(); }
TEST(CurvedAdaptation, InterfacesKeepTheirSidesAndPlanes3D) { expect_interfaces_kept_curved<3>(); }

template <int D>
void expect_same_mesh(const Mesh<D>& one, const Mesh<D>& two) {
  EXPECT_EQ(one.vertices().size(), two.vertices().size());
  EXPECT_TRUE(std::equal(one.vertices().begin(), one.vertices().end(), two.vertices().begin(), two.vertices().end()));
  EXPECT_TRUE(std::equal(one.elements().begin(), one.elements().end(), two.elements().begin(), two.elements().end()));
  EXPECT_TRUE(std::equal(one.edge_nodes().begin(), one.edge_nodes().end(), two.edge_nodes().begin(), two.edge_nodes().end()));
}

// The whole job, at 1 and 2 threads.
template <int D>
void expect_thread_independence() {
  AdaptedCase<D> one(true, 1), two(true, 2);
  expect_same_mesh(one.mesh, two.mesh);
}

TEST(CurvedAdaptation, OutputDoesNotDependOnThreads2D) { expect_thread_independence<2>(); }
TEST(CurvedAdaptation, OutputDoesNotDependOnThreads3D) { expect_thread_independence<3>(); }

}  // namespace
}  // namespace hocav
