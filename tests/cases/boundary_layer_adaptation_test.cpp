// The boundary-layer annulus and shell adapted in their implied metric with the P3 surrogate of their
// boundary: the wall's new vertices have to reach the geometry through the thin layers above them
// (docs/adaptation.md §Boundary settling).
#include <gtest/gtest.h>

#include "adapt/adaptation_driver.hpp"
#include "adapt/adaptation_loop.hpp"
#include "cases/cubed_sphere_shell.hpp"
#include "cases/polar_annulus.hpp"
#include "mesh/consistency.hpp"
#include "mesh/measure.hpp"
#include "metric/implied_metric.hpp"
#include "metric/metric_field.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

// A boundary split's point on the geometry would cross the thin first layer, so the splits leave the
// wall's new vertices on the input's segments. Settled only after the loop, most of them stay part
// of the way (a whole move folds the layer); settled after every pass, the next pass's swaps and
// moves mend the layer around them and every one arrives.
TEST(BoundaryLayerAdaptation, BringsTheRefinedWallOntoItsGeometry) {
  ShellLayering layering;
  layering.walls = LayerWalls::kInner;
  Mesh<2> mesh = generate_polar_annulus(layering, 1000);
  mesh.build_topology();
  const Index input_wall_facets = [&] {
    Index count = 0;
    for (Index f = 0; f < mesh.facet_count(); ++f) count += mesh.facet_ref(f) == 1;
    return count;
  }();
  const MetricField<2> field(mesh, implied_metric_at_vertices(mesh));
  const AdaptationMetric<2> metric(field, SizeBounds{});
  const P3Surrogate<2> geometry(mesh);
  const AdaptationRun run = adapt_to_metric(mesh, metric, &geometry, AdaptationSettings{});

  Index moved = 0;
  for (const AdaptationPass& pass : run.passes) moved += pass.settled + pass.partly_settled;
  EXPECT_GT(moved, 10);
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  ASSERT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
  for (const auto& element : mesh.elements())
    EXPECT_GT(signed_measure<2>({mesh.vertex(element[0]), mesh.vertex(element[1]), mesh.vertex(element[2])}), 0);
  Index wall_facets = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    wall_facets += mesh.facet_ref(f) == 1;
    for (Index v : mesh.facet(f)) {
      const Vec<2> x = mesh.vertex(v);
      EXPECT_LT(norm(geometry.project(x, {.ref = mesh.facet_ref(f)}).point - x), 1e-9) << v;
    }
  }
  EXPECT_GT(wall_facets, input_wall_facets + 10);  // the wall was refined
}

// On the shell the loop's splits and collapses fall below its convergence share while the settling
// still gets further each pass (nine wall vertices, up to 3.5e-3 inside the hole under a first layer
// 5.2e-3 thick, when the loop stopped there): it goes on until the settling stalls, and the
// settling after the loop finds every wall vertex on the geometry.
TEST(BoundaryLayerAdaptation, GoesOnWhileTheSettlingGetsFurther3D) {
  ShellLayering layering;
  layering.walls = LayerWalls::kInner;
  Mesh<3> mesh = generate_cubed_sphere_shell(layering, 5000);
  mesh.build_topology();
  const Mesh<3> input = mesh;
  AdaptationJob<3> job;
  job.threads = 2;
  job.measure_output = false;
  job.geometry = [](const Mesh<3>& m) { return std::unique_ptr<BoundaryGeometry<3>>(std::make_unique<P3Surrogate<3>>(m)); };
  const AdaptedMesh<3> adapted = run_adaptation_job(mesh, implied_metric_at_vertices(input), job, "the shell");

  const AdaptationRun& run = adapted.report.run;
  ASSERT_TRUE(run.converged);
  Index quiet_passes = 0;  // passes that changed fewer than the convergence share: the first no longer ends the loop
  for (const AdaptationPass& pass : run.passes)
    quiet_passes += pass.splits.done + pass.collapses.done <= 2.5e-3 * static_cast<double>(pass.vertices);
  EXPECT_GE(quiet_passes, 2);
  ASSERT_TRUE(adapted.report.settling.has_value());
  EXPECT_EQ(adapted.report.settling->off_geometry, 0);
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  EXPECT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
}

}  // namespace
}  // namespace hocav
