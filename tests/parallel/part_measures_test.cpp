// The output figures of a distributed curving measured by its parts (src/parallel/part_measures.hpp),
// without MPI: a curved cube cut into slabs, each slab measured in the field of its own vertices,
// the edges it leaves measured in the whole field, gives the whole mesh's figures; nodes moved in
// the whole mesh after the cut reach the parts as updates (apply_node_updates).
#include "parallel/part_measures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include "bezier/mesh_quality.hpp"
#include "cases/structured.hpp"
#include "mesh/boundary_vertices.hpp"
#include "metric/analytic_metric.hpp"
#include "report/curving_report.hpp"

namespace hocav {
namespace {

// The unit cube of 5 x 5 x 5 cells, P2 with every node off its edge's midpoint, in a shear layer.
struct CurvedCube {
  Mesh<3> straight = generate_cube(5);
  Mesh<3> mesh;
  std::unique_ptr<MetricField<3>> field;

  CurvedCube() {
    AnalyticMetricSpec spec;
    spec.name = "shear-sphere";
    spec.radius = 0.6;
    spec.width = 0.1;
    spec.h_min = 0.02;
    spec.h_max = 0.2;
    field = std::make_unique<MetricField<3>>(straight, analytic_metric_at_vertices(spec, straight));
    mesh = straight;
    mesh.build_topology();
    mesh.make_p2();
    for (Index e = 0; e < mesh.edge_count(); ++e) {
      const Vec<3> mid = mesh.edge_node(e);
      mesh.edge_node(e) = mid + Vec<3>{0.01 * std::sin(7 * mid[1]), 0.01 * std::cos(5 * mid[2]), 0.002 * (e % 5)};
    }
  }

  std::vector<MeshPart<3>> slabs(int count) const {
    std::vector<int> part_of;
    for (Index k = 0; k < mesh.element_count(); ++k) {
      double x = 0;
      for (Index v : mesh.element(k)) x += mesh.vertex(v)[0] / 4;
      part_of.push_back(std::min(count - 1, static_cast<int>(x * count)));
    }
    std::vector<MeshPart<3>> parts = split_mesh(mesh, part_of, count);
    for (MeshPart<3>& part : parts) part.mesh.build_topology();
    return parts;
  }

  // Every part measured (after the `written` nodes of the whole mesh reach it as updates), each
  // interface edge by the first part that holds it, its deferred edges in the whole field: the
  // figures the processes add up.
  PartMeasures measured_by(std::vector<MeshPart<3>>& parts, const std::vector<char>& written) const {
    const std::vector<bool> on_boundary = boundary_vertex_flags(mesh);
    std::vector<NodeUpdate<3>> updates;  // (the parts' global ids are the mesh's vertex ids)
    for (Index e = 0; e < mesh.edge_count(); ++e)
      if (written[e]) updates.push_back({mesh.edge_vertices(e), mesh.edge_node(e)});
    std::set<std::array<Index, 2>> held;  // the interface edges of the parts before
    PartMeasures all;
    for (MeshPart<3>& part : parts) {
      apply_node_updates<3>(part, updates);
      std::vector<SymMat<3>> log_metrics;
      std::vector<char> boundary;
      for (Index g : part.global_ids) {
        log_metrics.push_back(field->vertex_log_metric(g));
        boundary.push_back(on_boundary[g]);
      }
      std::vector<std::array<Index, 2>> elsewhere;
      for (const std::array<Index, 2>& edge : interface_edges_by_global_ends(part))
        if (!held.insert(edge).second) elsewhere.push_back(edge);
      const PartMeasures measured = measure_part<3>(part, MetricField<3>::from_log_metrics(part.mesh, log_metrics), boundary, elsewhere, 2);
      all.elements.insert(all.elements.end(), measured.elements.begin(), measured.elements.end());
      all.gains.insert(all.gains.end(), measured.gains.begin(), measured.gains.end());
      all.deferred.insert(all.deferred.end(), measured.deferred.begin(), measured.deferred.end());
    }
    for (const auto& [a, b] : all.deferred) all.gains.push_back(edge_gain(mesh, *field, mesh.find_edge(a, b)).value);
    return all;
  }

  // The parts' figures are the whole mesh's: each element and each volume edge once.
  void expect_whole_figures(const PartMeasures& measured) const {
    const auto whole = summarize_jacobian_quality(mesh_jacobian_quality(mesh, kReportedRefinement));
    const auto parts = summarize_jacobian_quality(measured.elements);
    EXPECT_EQ(parts.min_normalized_jacobian.count, whole.min_normalized_jacobian.count);
    EXPECT_NEAR(parts.min_normalized_jacobian.min, whole.min_normalized_jacobian.min, 1e-12);
    EXPECT_NEAR(parts.min_normalized_jacobian.average, whole.min_normalized_jacobian.average, 1e-12);
    EXPECT_NEAR(parts.scaled_jacobian.average, whole.scaled_jacobian.average, 1e-12);
    const std::vector<double> gains = volume_edge_gains(mesh, *field);
    ASSERT_EQ(measured.gains.size(), gains.size());
    const auto sum = [](const std::vector<double>& values) { return std::accumulate(values.begin(), values.end(), 0.0); };
    EXPECT_NEAR(sum(measured.gains), sum(gains), 1e-9 * std::abs(sum(gains)));
    EXPECT_NEAR(*std::max_element(measured.gains.begin(), measured.gains.end()), *std::max_element(gains.begin(), gains.end()), 1e-12);
    EXPECT_GT(std::count_if(gains.begin(), gains.end(), [](double gain) { return gain != 0; }), 100);  // curved edges measured
  }
};

TEST(PartMeasures, PartsMeasureTheWholeMeshOnce) {
  const CurvedCube cube;
  const std::vector<char> none(static_cast<std::size_t>(cube.mesh.edge_count()), 0);
  for (int count : {1, 2, 3}) {
    SCOPED_TRACE(count);
    std::vector<MeshPart<3>> parts = cube.slabs(count);
    const PartMeasures measured = cube.measured_by(parts, none);
    cube.expect_whole_figures(measured);
    // Curved nodes just past an interface lie outside the part: their edges are deferred.
    if (count > 1) {
      EXPECT_GT(measured.deferred.size(), 0u);
    }
  }
}

TEST(PartMeasures, NodesMovedAfterTheCutReachTheParts) {
  CurvedCube cube;
  std::vector<MeshPart<3>> parts = cube.slabs(3), stale = cube.slabs(3);
  // A later round moves the nodes of every third edge, inside a slab or on an interface.
  std::vector<char> written(static_cast<std::size_t>(cube.mesh.edge_count()), 0);
  for (Index e = 0; e < cube.mesh.edge_count(); e += 3) {
    cube.mesh.edge_node(e) = cube.mesh.edge_node(e) + Vec<3>{0.004, -0.003, 0.002};
    written[e] = 1;
  }
  cube.expect_whole_figures(cube.measured_by(parts, written));
  // Without the updates the parts measure the nodes of the cut: other figures.
  const std::vector<char> none(written.size(), 0);
  const PartMeasures measured = cube.measured_by(stale, none);
  const std::vector<double> gains = volume_edge_gains(cube.mesh, *cube.field);
  EXPECT_NE(std::accumulate(measured.gains.begin(), measured.gains.end(), 0.0), std::accumulate(gains.begin(), gains.end(), 0.0));
}

}  // namespace
}  // namespace hocav
