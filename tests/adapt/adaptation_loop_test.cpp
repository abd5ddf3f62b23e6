// The adaptation loop end to end on generated cases: the mesh comes out consistent, of the same
// measure, with its boundary refs, corners and ridges, and unit in its metric (share of unit edges
// and element qualities asserted); and each pass on its own does what it says.
#include "adapt/adaptation_loop.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>
#include <utility>

#include "../mesh/inner_facet_meshes.hpp"
#include "../mesh/turned_facets.hpp"
#include "adapt/adaptation_mesh.hpp"
#include "adapt_test_support.hpp"
#include "mesh/measure.hpp"
#include "metric/metric_field.hpp"
#include "report/mesh_statistics.hpp"

namespace hocav {
namespace {

// The figures `hocav stats --metric` gives for the mesh in the (clamped) metric of the run.
template <int D>
MetricStatistics measured(const Mesh<D>& mesh, const AdaptationMetric<D>& metric) {
  std::vector<double> rows;
  Index hint = kNoIndex;
  for (const auto& x : mesh.vertices())
    for (double entry : metric.metric_at(x, hint).entries) rows.push_back(entry);
  Mesh<D> copy = mesh;
  return *compute_mesh_statistics(copy, rows).metric;
}

// Per facet ref: the measure of its facets (a boundary piece keeps its size when it keeps its ref).
template <int D>
std::map<int, double> boundary_measure_by_ref(const Mesh<D>& mesh) {
  std::map<int, double> out;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const auto& v = mesh.facet(f);
    if constexpr (D == 2)
      out[mesh.facet_ref(f)] += norm(mesh.vertex(v[1]) - mesh.vertex(v[0]));
    else
      out[mesh.facet_ref(f)] += 0.5 * norm(cross(mesh.vertex(v[1]) - mesh.vertex(v[0]), mesh.vertex(v[2]) - mesh.vertex(v[0])));
  }
  return out;
}

template <int D>
AdaptationMetric<D> linear_metric(double h_min) {
  AnalyticMetricSpec spec;
  spec.name = "linear";
  spec.h_min = h_min;
  return AdaptationMetric<D>(spec, {});
}

// `new_corners`: the corners the classification adds (where feature lines end; none on a cube).
template <int D>
void expect_adapted(Mesh<D>& mesh, const AdaptationMetric<D>& metric, double unit_share, double mean_quality, double min_quality,
                    std::size_t new_corners = 0) {
  const auto corners_before = mesh.corners().size();
  const auto refs_before = boundary_measure_by_ref(mesh);
  const AdaptationRun run = adapt_to_metric<D>(mesh, metric, nullptr, {});
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_TRUE(mesh.is_compact());
  EXPECT_TRUE(run.converged);
  EXPECT_NEAR(total_measure(mesh), 1, 1e-9);
  const auto refs_after = boundary_measure_by_ref(mesh);
  ASSERT_EQ(refs_after.size(), refs_before.size());
  for (const auto& [ref, measure] : refs_before) EXPECT_NEAR(refs_after.at(ref), measure, 1e-9) << "facet ref " << ref;
  EXPECT_EQ(mesh.corners().size(), corners_before + new_corners);
  const MetricStatistics m = measured(mesh, metric);
  EXPECT_GE(m.unit_share, unit_share);
  EXPECT_GE(m.quality_mean, mean_quality);
  EXPECT_GE(m.quality_min, min_quality);
  // Each pass after the first few changes less than the one before it ends with: no oscillation.
  const AdaptationPass& last = run.passes.back();
  EXPECT_LE(last.splits.done + last.collapses.done,
            run.passes[run.passes.size() / 2].splits.done + run.passes[run.passes.size() / 2].collapses.done);
}

TEST(AdaptationLoop, SquareInTheLinearMetricBecomesUnit) {
  Mesh<2> mesh = adapt_test::unit_mesh<2>(10);
  expect_adapted<2>(mesh, linear_metric<2>(0.01), 0.95, 0.85, 0.3);
  EXPECT_GT(mesh.element_count(), 500);  // refined toward the layer
}

TEST(AdaptationLoop, CubeInTheLinearMetricBecomesUnit) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(4);
  const auto ridges_before = mesh.ridges().size();
  // 96%: the loop's open window (docs/adaptation.md §The loop); 95.4% with collapses kept within √2.
  expect_adapted<3>(mesh, linear_metric<3>(0.02), 0.96, 0.75, 0.05);
  EXPECT_GT(mesh.ridges().size(), ridges_before);  // the cube's edges, split along them
  // Every ridge stays on a cube edge: two of its coordinates are 0 or 1.
  for (Index l : mesh.ridges())
    for (Index v : mesh.line(l)) {
      int on_sides = 0;
      for (int i = 0; i < 3; ++i) on_sides += std::abs(mesh.vertex(v)[i]) < 1e-12 || std::abs(mesh.vertex(v)[i] - 1) < 1e-12;
      EXPECT_GE(on_sides, 2);
    }
}

// The loop's window (docs/adaptation.md §The loop) as the run reports it: open from the first pass,
// collapses making edges up to 2; closed for good after a pass that stalled (past the busiest, more
// than 0.9 × the changes of the one before and not more than 1/0.9 ×; or more than 0.8 × with a
// vertex count that moved by less than 5% of the changes; or three such flat passes in a row; or
// one that took the vertex and element counts back to those of the pass two before it), up to √2 then. A run
// capped before that stops with it open.
TEST(AdaptationLoop, TheRunReportsItsWindowPassByPass) {
  const Mesh<2> input = adapt_test::unit_mesh<2>(10);
  const AdaptationMetric<2> metric = linear_metric<2>(0.01);
  Mesh<2> mesh = input;
  const AdaptationRun run = adapt_to_metric<2>(mesh, metric, nullptr, {});
  const auto changes = [](const AdaptationPass& pass) { return static_cast<double>(pass.splits.done + pass.collapses.done); };
  const auto closed = std::find_if(run.passes.begin(), run.passes.end(), [](const AdaptationPass& pass) { return !pass.window_open; });
  ASSERT_NE(closed, run.passes.end()) << "the window never closed";
  ASSERT_GE(closed - run.passes.begin(), 2);
  const bool in_band = changes(closed[-1]) > 0.9 * changes(closed[-2]) && 0.9 * changes(closed[-1]) <= changes(closed[-2]);
  const bool ping_pong = changes(closed[-1]) > 0.8 * changes(closed[-2]) &&
                         std::abs(static_cast<double>(closed[-1].vertices - closed[-2].vertices)) < 0.05 * changes(closed[-1]);
  const auto flat = [&](auto pass) {
    return std::abs(static_cast<double>(pass[0].vertices - pass[-1].vertices)) < 0.05 * changes(pass[0]);
  };
  const bool three_flat = closed - run.passes.begin() >= 4 && flat(closed - 1) && flat(closed - 2) && flat(closed - 3);
  const auto counts = [](const AdaptationPass& pass) { return std::pair(pass.vertices, pass.elements); };
  const bool back_where_it_was = closed - run.passes.begin() >= 3 && counts(closed[-1]) == counts(closed[-3]) &&
                                 counts(closed[-1]) != counts(closed[-2]);
  EXPECT_TRUE(in_band || ping_pong || three_flat || back_where_it_was) << "a jump in the changes is new work, not a stall";
  for (auto pass = run.passes.begin(); pass != run.passes.end(); ++pass) {
    EXPECT_EQ(pass->window_open, pass < closed) << "pass " << pass - run.passes.begin() + 1;
    EXPECT_EQ(pass->collapse_length_bound, pass < closed ? 2 : std::sqrt(2.0)) << "pass " << pass - run.passes.begin() + 1;
  }
  EXPECT_FALSE(run.stopped_with_window_open);
  Mesh<2> capped = input;
  AdaptationSettings two_passes;
  two_passes.max_passes = 2;
  const AdaptationRun capped_run = adapt_to_metric<2>(capped, metric, nullptr, two_passes);
  ASSERT_FALSE(capped_run.converged);
  EXPECT_TRUE(capped_run.passes.back().window_open);
  EXPECT_TRUE(capped_run.stopped_with_window_open);
}

// A first pass limited to no vertex tries nothing, and the loop, seeing no change, stops there: the
// mesh, twice too coarse for the metric, comes out as it went in. A region of the wrong size is refused.
TEST(AdaptationLoop, TheFirstPassTriesOnlyTheGivenVertices) {
  const Mesh<2> input = adapt_test::unit_mesh<2>(10);
  Mesh<2> mesh = input;
  AdaptationSettings settings;
  settings.first_pass_vertices.assign(static_cast<std::size_t>(mesh.vertex_count()), 0);
  const AdaptationRun run = adapt_to_metric<2>(mesh, adapt_test::uniform_metric<2>(0.05), nullptr, settings);
  ASSERT_EQ(run.passes.size(), 1u);
  EXPECT_TRUE(run.converged);
  EXPECT_EQ(run.passes[0].splits.done + run.passes[0].collapses.done + run.passes[0].swaps.done + run.passes[0].moves.done, 0);
  EXPECT_EQ(mesh.element_count(), input.element_count());
  ASSERT_EQ(mesh.vertex_count(), input.vertex_count());
  Mesh<2> free = input;
  adapt_to_metric<2>(free, adapt_test::uniform_metric<2>(0.05), nullptr, {});
  EXPECT_GT(free.element_count(), 2 * input.element_count());  // what the limit kept from happening
  settings.first_pass_vertices.pop_back();
  EXPECT_THROW(adapt_to_metric<2>(mesh, adapt_test::uniform_metric<2>(0.05), nullptr, settings), Error);
}

// With first_pass_unfinished_edges the first pass also tries the ends of the edges outside the unit
// window: the square twice too coarse, no vertex given, is adapted as if the run were free.
TEST(AdaptationLoop, TheFirstPassCanAlsoTryTheUnfinishedEdges) {
  const Mesh<2> input = adapt_test::unit_mesh<2>(10);
  Mesh<2> mesh = input;
  AdaptationSettings settings;
  settings.first_pass_vertices.assign(static_cast<std::size_t>(mesh.vertex_count()), 0);
  settings.first_pass_unfinished_edges = true;
  const AdaptationRun run = adapt_to_metric<2>(mesh, adapt_test::uniform_metric<2>(0.05), nullptr, settings);
  EXPECT_GT(run.passes[0].splits.done, 0);
  EXPECT_GT(mesh.element_count(), 2 * input.element_count());
  adapt_test::expect_closed_and_consistent(mesh);
}

// The first pass also tries the poor elements outside the region: the square, unit in its metric
// but for the vertex at its centre moved 0.09 toward its right neighbour, is mended with no vertex given.
TEST(AdaptationLoop, TheFirstPassAlsoTriesThePoorElements) {
  Mesh<2> mesh = adapt_test::unit_mesh<2>(10);
  const AdaptationMetric<2> metric = adapt_test::uniform_metric<2>(0.1);
  Index centre = kNoIndex;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (norm(mesh.vertex(v) - Vec<2>{0.5, 0.5}) < 1e-12) centre = v;
  ASSERT_NE(centre, kNoIndex);
  mesh.vertex(centre)[0] += 0.09;
  ASSERT_LT(measured(mesh, metric).quality_min, kPoorQuality);
  AdaptationSettings settings;
  settings.first_pass_vertices.assign(static_cast<std::size_t>(mesh.vertex_count()), 0);
  adapt_to_metric<2>(mesh, metric, nullptr, settings);
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_GE(measured(mesh, metric).quality_min, 0.5);
}

// Threads change when work is done, never what is done: the same vertices, elements and facets.
// The shear layer crosses the cube's sides: boundary splits there re-star facets next to edges
// whose previews were made at the chunk's start (their facet ids change while their shells' elements
// keep their vertices; the previews once missed that).
TEST(AdaptationLoop, OutputDoesNotDependOnTheThreadCount) {
  const Mesh<3> input = adapt_test::unit_mesh<3>(4);
  AnalyticMetricSpec shear;
  shear.name = "shear-sphere";
  shear.h_min = 0.03;
  shear.h_max = 0.2;
  shear.radius = 0.6;
  const AdaptationMetric<3> metric(shear, {});
  std::vector<Mesh<3>> outputs;
  for (int threads : {1, 2, 3}) {
    outputs.push_back(input);
    AdaptationSettings settings;
    settings.threads = threads;
    adapt_to_metric<3>(outputs.back(), metric, nullptr, settings);
  }
  for (std::size_t i = 1; i < outputs.size(); ++i) {
    ASSERT_EQ(outputs[i].vertex_count(), outputs[0].vertex_count());
    EXPECT_TRUE(std::ranges::equal(outputs[i].vertices(), outputs[0].vertices()));
    EXPECT_TRUE(std::ranges::equal(outputs[i].elements(), outputs[0].elements()));
    ASSERT_EQ(outputs[i].facet_count(), outputs[0].facet_count());
  }
}

// The sorted vertex positions of a facet or line: what a required entity must still be after adapting.
template <int D, std::size_t N>
std::vector<std::array<double, D>> sorted_points(const Mesh<D>& mesh, const std::array<Index, N>& vertices) {
  std::vector<std::array<double, D>> points;
  for (Index v : vertices) {
    std::array<double, D> point;
    for (int i = 0; i < D; ++i) point[i] = mesh.vertex(v)[i];
    points.push_back(point);
  }
  std::sort(points.begin(), points.end());
  return points;
}

// Required edges and triangles (Gamma's RequiredEdges, RequiredTriangles) come out as they went in,
// listed as required, while the loop refines everything around them.
template <int D>
void expect_required_kept(Mesh<D> mesh) {
  // Required: the boundary facets on the side x = 0 (2D: they are the required edges) and, in 3D,
  // the feature lines on it.
  std::vector<Index>& required_facets = D == 2 ? mesh.required_edges() : mesh.required_triangles();
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (std::all_of(mesh.facet(f).begin(), mesh.facet(f).end(), [&](Index v) { return mesh.vertex(v)[0] == 0; }))
      required_facets.push_back(f);
  if constexpr (D == 3)
    for (Index l = 0; l < mesh.line_count(); ++l)
      if (mesh.vertex(mesh.line(l)[0])[0] == 0 && mesh.vertex(mesh.line(l)[1])[0] == 0) mesh.required_edges().push_back(l);
  const auto points_of = [](const Mesh<D>& m, bool lines) {
    std::vector<std::vector<std::array<double, D>>> out;
    for (Index id : lines ? m.required_edges() : (D == 2 ? m.required_edges() : m.required_triangles()))
      out.push_back(lines && D == 3 ? sorted_points<D>(m, m.line(id)) : sorted_points<D>(m, m.facet(id)));
    std::sort(out.begin(), out.end());
    return out;
  };
  const auto facets_before = points_of(mesh, false), lines_before = points_of(mesh, true);
  ASSERT_FALSE(facets_before.empty());
  const Index elements_before = mesh.element_count();
  adapt_to_metric<D>(mesh, linear_metric<D>(0.02), nullptr, {});
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_GT(mesh.element_count(), 4 * elements_before);  // refined, also along x = 0 (a fine direction)
  EXPECT_EQ(points_of(mesh, false), facets_before);
  EXPECT_EQ(points_of(mesh, true), lines_before);
}

TEST(AdaptationLoop, RequiredEdgesAndTrianglesAreKept) {
  expect_required_kept<2>(adapt_test::unit_mesh<2>(6));
  expect_required_kept<3>(adapt_test::unit_mesh<3>(3));
}

using mesh_test::centroid_x;
using mesh_test::two_refs_across_an_interface;

// Per element ref, the measure of its elements, and whether each lies on its side of x = 0.5.
template <int D>
void expect_refs_on_their_sides(const Mesh<D>& mesh) {
  std::map<int, double> measure;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    ASSERT_EQ(mesh.element_ref(k), centroid_x(mesh, k) < 0.5 ? 1 : 2) << "element " << k << " at x = " << centroid_x(mesh, k);
    measure[mesh.element_ref(k)] += element_measure(mesh, k);
  }
  EXPECT_NEAR(measure[1], 0.5, 1e-9);
  EXPECT_NEAR(measure[2], 0.5, 1e-9);
}

// A mesh with an interface between element refs adapts as well as one without (its edges are split
// and collapsed with the elements on both sides), every element keeping its side's ref and the
// interface its measure (expect_adapted: every facet ref's).
TEST(AdaptationLoop, AnInterfaceBetweenElementRefsIsAdaptedWithBothSides) {
  Mesh<2> square = two_refs_across_an_interface<2>(10);
  expect_adapted<2>(square, linear_metric<2>(0.01), 0.95, 0.85, 0.3, 2);  // the interface's ends
  expect_refs_on_their_sides(square);
  Mesh<3> cube = two_refs_across_an_interface<3>(4);
  expect_adapted<3>(cube, linear_metric<3>(0.02), 0.96, 0.75, 0.05, 4);  // the interface square's corners
  expect_refs_on_their_sides(cube);
}

// Four element refs meeting at a point (2D) or along a line (3D): the junction is a corner or a
// feature line, and every element keeps its quadrant's ref.
TEST(AdaptationLoop, FourRefsMeetingAtAJunctionAreAdapted) {
  const auto expect_quadrants = [](const auto& mesh) {
    std::map<int, double> measure;
    for (Index k = 0; k < mesh.element_count(); ++k) {
      double x = 0, y = 0;
      for (Index v : mesh.element(k)) x += mesh.vertex(v)[0], y += mesh.vertex(v)[1];
      x /= static_cast<double>(mesh.element(k).size()), y /= static_cast<double>(mesh.element(k).size());
      ASSERT_EQ(mesh.element_ref(k), 1 + (x > 0.5) + 2 * (y > 0.5)) << "element " << k << " at " << x << ", " << y;
      measure[mesh.element_ref(k)] += element_measure(mesh, k);
    }
    for (int ref = 1; ref <= 4; ++ref) EXPECT_NEAR(measure[ref], 0.25, 1e-9) << "ref " << ref;
  };
  // New corners: the interfaces' four ends on the hull and the centre (2D); the two planes'
  // crossings of the cube's edges (eight) and the junction line's two ends (3D).
  Mesh<2> square = mesh_test::four_refs_by_quadrant<2>(10);
  expect_adapted<2>(square, linear_metric<2>(0.01), 0.95, 0.85, 0.3, 5);
  expect_quadrants(square);
  Mesh<3> cube = mesh_test::four_refs_by_quadrant<3>(4);
  expect_adapted<3>(cube, linear_metric<3>(0.02), 0.96, 0.75, 0.05, 10);
  expect_quadrants(cube);
}

// A baffle (facets inside one element ref) given with its facets either way adapts as well as the
// interface above: its patch is oriented alike first (Mesh::orient_boundary_facets_outward).
TEST(AdaptationLoop, ABaffleGivenEitherWayIsAdapted) {
  // The copy keeps no Corners or Edges: the square's and the cube's corners come back by angle,
  // with the baffle's ends.
  Mesh<2> square = mesh_test::with_facets_turned(mesh_test::baffle_across_the_middle<2>(10), 2);
  expect_adapted<2>(square, linear_metric<2>(0.01), 0.95, 0.85, 0.3, 4 + 2);
  Mesh<3> cube = mesh_test::with_facets_turned(mesh_test::baffle_across_the_middle<3>(4), 2);
  expect_adapted<3>(cube, linear_metric<3>(0.02), 0.96, 0.75, 0.05, 8 + 4);
}

TEST(AdaptationLoop, CoarseningAFineMeshInAUniformMetric) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(8);
  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(0.3);
  const Index before = mesh.element_count();
  // Short edges that no collapse within √2 removes go while the loop's window is open
  // (docs/adaptation.md §The loop): 98.8% unit, 87.4% with the window closed from the start.
  expect_adapted<3>(mesh, metric, 0.95, 0.8, 0.1);
  EXPECT_LT(mesh.element_count(), before / 4);
}

// The unit cube with one facet ref and no tags: its edges are ridges of its shape only.
Mesh<3> untagged_one_ref_cube(int cells_per_side) {
  const Mesh<3> cube = adapt_test::unit_mesh<3>(cells_per_side);
  Mesh<3> mesh;
  for (const auto& point : cube.vertices()) mesh.add_vertex(point);
  for (Index k = 0; k < cube.element_count(); ++k) mesh.add_element(cube.element(k), 1);
  for (Index f = 0; f < cube.facet_count(); ++f) mesh.add_facet(cube.facet(f), 1);
  mesh.build_topology();
  return mesh;
}

// A loop told to take its ridges from the tags only (a distributed part's) finds none in the shape;
// the default finds the cube's twelve edges and eight corners.
TEST(AdaptationLoop, RidgesComeFromTheShapeUnlessTheTagsAloneAreAsked) {
  const AdaptationMetric<3> metric = adapt_test::uniform_metric<3>(0.25);
  Mesh<3> from_shape = untagged_one_ref_cube(3), from_tags = untagged_one_ref_cube(3);
  adapt_to_metric<3>(from_shape, metric, nullptr, {});
  AdaptationSettings tags_only;
  tags_only.ridges_from_shape = false;
  adapt_to_metric<3>(from_tags, metric, nullptr, tags_only);
  adapt_test::expect_closed_and_consistent(from_tags);
  EXPECT_EQ(from_shape.corners().size(), 8U);
  EXPECT_GE(from_shape.line_count(), 12);
  EXPECT_EQ(from_tags.corners().size(), 0U);
  EXPECT_EQ(from_tags.line_count(), 0);
}

TEST(AdaptationLoop, SizeBoundsClampTheMetric) {
  AnalyticMetricSpec spec;
  spec.name = "uniform";
  spec.h = 0.01;
  const AdaptationMetric<2> clamped(spec, {0.0, 0.2}), bounded_below(spec, {0.05, 1.0});
  Index hint = kNoIndex;
  EXPECT_NEAR(clamped.metric_at({0.5, 0.5}, hint)(0, 0), 1 / 0.0001, 1e-6);  // within the bounds: unchanged
  EXPECT_NEAR(bounded_below.metric_at({0.5, 0.5}, hint)(0, 0), 1 / 0.0025, 1e-6);
  EXPECT_NEAR(bounded_below.metric_at({0.5, 0.5}, hint)(0, 1), 0, 1e-9);
}

// Each pass alone: a split pass leaves no edge longer than the split length among those it could
// cut, a collapse pass no short interior edge it could remove, and neither breaks the mesh.
TEST(AdaptationPasses, SplitAndCollapseEachDoWhatTheySay) {
  Mesh<2> mesh = adapt_test::unit_mesh<2>(6);
  const AdaptationMetric<2> fine = adapt_test::uniform_metric<2>(0.05);
  AdaptationMesh<2> am(mesh, fine, nullptr, 45);
  const AdaptationLimits limits;
  ThreadPool pool(2);
  const Index before = mesh.vertex_count();
  const OperationCount splits = split_long_edges(am, limits, pool).count;
  EXPECT_GT(splits.done, 0);
  EXPECT_EQ(mesh.vertex_count(), before + splits.done);
  adapt_test::expect_closed_and_consistent(mesh);
  const AdaptationMetric<2> coarse = adapt_test::uniform_metric<2>(0.5);
  AdaptationMesh<2> coarse_am(mesh, coarse, nullptr, 45);
  const Index vertices = mesh.live_vertex_count();
  const OperationCount collapses = collapse_short_edges(coarse_am, limits, pool);
  EXPECT_GT(collapses.done, 0);
  EXPECT_EQ(mesh.live_vertex_count(), vertices - collapses.done);
  adapt_test::expect_closed_and_consistent(mesh);
  mesh.compact();
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_NEAR(total_measure(mesh), 1, 1e-12);
}

// A distributed part's split rule (SplitsAtRequiredVertices::kNextToFineRequiredFacets) cuts an edge
// between two required vertices that lies on no required facet: such an edge crosses the part from
// one interface vertex to another, and left long it kept the splits beside it cutting ever thinner
// elements (docs/distributed.md §Interfaces refined first). A metric fine across the square's
// diagonals makes them the only long edges.
TEST(AdaptationPasses, ADistributedPartSplitsAnEdgeBetweenTwoRequiredVertices) {
  Mesh<2> mesh = adapt_test::unit_mesh<2>(4);
  const auto interior = [&](Index v) {
    return mesh.vertex(v)[0] > 0 && mesh.vertex(v)[0] < 1 && mesh.vertex(v)[1] > 0 && mesh.vertex(v)[1] < 1;
  };
  Index a = kNoIndex, b = kNoIndex;  // a diagonal between two inner vertices
  for (const auto& element : mesh.elements())
    for (int i = 0; i < 3 && a == kNoIndex; ++i) {
      const Index x = element[i], y = element[(i + 1) % 3];
      if (interior(x) && interior(y) && norm(mesh.vertex(y) - mesh.vertex(x)) > 0.3)
        std::tie(a, b) = std::pair(std::min(x, y), std::max(x, y));
    }
  ASSERT_NE(a, kNoIndex);
  const Vec2 along = (1 / norm(mesh.vertex(b) - mesh.vertex(a))) * (mesh.vertex(b) - mesh.vertex(a));
  SymMat<2> metric;  // size 0.2 along the diagonals (they are 1.77 long), 1 across
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) metric(i, j) = (i == j ? 1.0 : 0.0) + (1 / 0.04 - 1) * along[i] * along[j];
  const Mesh<2> back = mesh;
  const MetricField<2> field(back, std::vector<SymMat<2>>(static_cast<std::size_t>(back.vertex_count()), metric));
  const AdaptationMetric<2> adaptation_metric(field, SizeBounds{});
  mesh.required_vertices() = {a, b};
  AdaptationMesh<2> am(mesh, adaptation_metric, nullptr, 45);
  AdaptationLimits limits;
  limits.splits_at_required_vertices = SplitsAtRequiredVertices::kNextToFineRequiredFacets;
  ThreadPool pool(1);
  EXPECT_GT(split_long_edges(am, limits, pool).count.done, 0);
  adapt_test::expect_closed_and_consistent(mesh);
  for (const auto& element : mesh.elements())
    EXPECT_FALSE(std::count(element.begin(), element.end(), a) && std::count(element.begin(), element.end(), b))
        << "the edge between the required vertices " << a << " and " << b << " is still there";
  limits.splits_at_required_vertices = SplitsAtRequiredVertices::kNone;  // the last runs': none at a required vertex
  Mesh<2> again = adapt_test::unit_mesh<2>(4);
  again.required_vertices() = {a, b};
  AdaptationMesh<2> am_again(again, adaptation_metric, nullptr, 45);
  split_long_edges(am_again, limits, pool);
  bool kept = false;
  for (const auto& element : again.elements())
    kept = kept || (std::count(element.begin(), element.end(), a) && std::count(element.begin(), element.end(), b));
  EXPECT_TRUE(kept);
}

// A boundary split whose point on the geometry would turn its facets past the feature angle goes
// halfway there (mmg bisects the same way), not back to the straight middle: the bottom side's
// geometry 0.15 below the square, its edges 0.25 long (the point turns the new facets by 50°,
// halfway by 31°).
TEST(AdaptationPasses, ABoundarySplitGoesAsCloseToTheGeometryAsItsFacetsAllow) {
  Mesh<2> mesh = adapt_test::unit_mesh<2>(4);
  AnalyticBoundary<2> sides = adapt_test::unit_box_sides<2>();
  sides.add(1, AnalyticSurface<2>::plane(Vec2{{0, -0.15}}, Vec2{{0, 1}}));
  const AdaptationMetric<2> metric = adapt_test::uniform_metric<2>(0.15);
  AdaptationMesh<2> am(mesh, metric, &sides, 45);
  AdaptationLimits limits;
  limits.cos_feature_angle = std::cos(std::numbers::pi / 4);
  ThreadPool pool(1);
  EXPECT_GT(split_long_edges(am, limits, pool).count.done, 0);
  for (const double x : {0.125, 0.375, 0.625, 0.875}) {
    Index v = kNoIndex;
    for (Index w = 0; w < mesh.vertex_count(); ++w)
      if (!mesh.vertex_removed(w) && std::abs(mesh.vertex(w)[0] - x) < 1e-12 && mesh.vertex(w)[1] < 0.01) v = w;
    ASSERT_NE(v, kNoIndex) << x;
    EXPECT_NEAR(mesh.vertex(v)[1], -0.075, 1e-12) << x;
  }
  adapt_test::expect_closed_and_consistent(mesh);
}

// The quality AdaptationMesh keeps per element is the one evaluated afresh, after every operator.
template <int D>
void expect_kept_qualities_current(const AdaptationMesh<D>& am) {
  for (Index k = 0; k < am.mesh().element_count(); ++k) ASSERT_EQ(am.quality(k), am.quality(am.mesh().element(k))) << "element " << k;
}

TEST(AdaptationPasses, KeptQualitiesFollowEveryOperation) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(4);
  const AdaptationMetric<3> metric = linear_metric<3>(0.05);
  AdaptationMesh<3> am(mesh, metric, nullptr, 45);
  const AdaptationLimits limits;
  ThreadPool pool(2);
  expect_kept_qualities_current(am);
  EXPECT_GT(split_long_edges(am, limits, pool).count.done, 0);
  expect_kept_qualities_current(am);
  EXPECT_GT(swap_for_quality(am, limits, 0, pool).done, 0);
  expect_kept_qualities_current(am);
  EXPECT_GT(smooth_vertices(am, limits, pool).done, 0);
  expect_kept_qualities_current(am);
  mesh.compact();
  expect_kept_qualities_current(am);
  const AdaptationMetric<3> coarse = adapt_test::uniform_metric<3>(0.5);
  AdaptationMesh<3> coarse_am(mesh, coarse, nullptr, 45);
  EXPECT_GT(collapse_short_edges(coarse_am, limits, pool).done, 0);
  expect_kept_qualities_current(coarse_am);
  mesh.compact();
  expect_kept_qualities_current(coarse_am);
}

TEST(AdaptationPasses, SwapsAndSmoothingRaiseTheWorstQuality) {
  Mesh<3> mesh = adapt_test::unit_mesh<3>(3);
  const AdaptationMetric<3> metric = linear_metric<3>(0.05);
  AdaptationMesh<3> am(mesh, metric, nullptr, 45);
  const AdaptationLimits limits;
  ThreadPool pool(2);
  const auto worst = [&] {
    double q = 1;
    for (Index k = 0; k < mesh.element_count(); ++k) q = std::min(q, am.quality(k));
    return q;
  };
  split_long_edges(am, limits, pool);
  mesh.compact();
  const double before = worst();
  const OperationCount swaps = swap_for_quality(am, limits, 0, pool);
  const OperationCount moves = smooth_vertices(am, limits, pool);
  EXPECT_GT(swaps.done + moves.done, 0);
  EXPECT_GE(worst(), before);  // neither ever lowers the worst element of what it changes
  adapt_test::expect_closed_and_consistent(mesh);
  EXPECT_NEAR(total_measure(mesh), 1, 1e-9);
}

}  // namespace
}  // namespace hocav
