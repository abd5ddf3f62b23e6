// The boundary-layer annulus adapted in its implied metric with the P3 surrogate of its boundary: the
// wall's new vertices have to reach the geometry through the thin layers above them
// (docs/adaptation.md §Boundary settling).
#include <gtest/gtest.h>

#include "adapt/adaptation_loop.hpp"
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

}  // namespace
}  // namespace hocav
