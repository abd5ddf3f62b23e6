// Edge optimization throughput (docs/method.md §7) on realistic edges: every edge of a back mesh of about 105k
// elements, in an adapted-looking shear field (size ratio h_max/h_min = 300 across a curved layer), optimized
// with the default options (Simpson rule, localization included, hint = an element of the edge's first vertex),
// the vertices' metrics made once per vertex.
// Micro benchmarks split the cost: one localization from a near hint, one ExpFrechet construction, one
// EdgeLengthFunction::evaluate at each order, one kink analysis and one curvature along a direction.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <vector>

#include "cases/structured.hpp"
#include "curve/edge_optimizer.hpp"
#include "curve/kink_descent.hpp"
#include "geom/orthonormal_complement.hpp"
#include "geom/sym_functions.hpp"
#include "metric/analytic_metric.hpp"
#include "metric/metric_field.hpp"

namespace hocav {
namespace {

// Unit square 230² (105,800 triangles) or unit cube 26³ (105,456 tetrahedra); the shear layer of
// radius 0.75 around the origin crosses both diagonally.
template <int D>
Mesh<D> back_mesh() {
  if constexpr (D == 2)
    return generate_square(230);
  else
    return generate_cube(26);
}

template <int D>
struct EdgeCase {
  MetricField<D> field;
  std::vector<std::array<Index, 2>> edges;
  std::vector<Index> vertex_element;  // an element of each vertex: the hint of the edge's first node
};

template <int D>
const EdgeCase<D>& edge_case() {
  static const EdgeCase<D> instance = [] {
    Mesh<D> mesh = back_mesh<D>();
    AnalyticMetricSpec spec;
    spec.name = D == 2 ? "shear-circle" : "shear-sphere";
    spec.h_max = 0.1;
    spec.h_min = spec.h_max / 300;
    spec.width = 0.1;
    MetricField<D> field(mesh, analytic_metric_at_vertices<D>(spec, mesh));
    mesh.build_edges();
    std::vector<std::array<Index, 2>> edges(static_cast<std::size_t>(mesh.edge_count()));
    for (Index e = 0; e < mesh.edge_count(); ++e) edges[static_cast<std::size_t>(e)] = mesh.edge_vertices(e);
    std::vector<Index> vertex_element(static_cast<std::size_t>(mesh.vertex_count()), kNoIndex);
    for (Index k = 0; k < mesh.element_count(); ++k)
      for (Index v : mesh.element(k)) vertex_element[static_cast<std::size_t>(v)] = k;
    return EdgeCase<D>{std::move(field), std::move(edges), std::move(vertex_element)};
  }();
  return instance;
}

// The straight midpoints of 1,024 edges spread over the mesh, each with its edge's length function, the
// back-mesh sample there and that element's log-metric gradient: the inputs of the kernel benchmarks.
template <int D>
struct MidpointInput {
  EdgeLengthFunction<D> function;
  Vec<D> node, edge_direction;
  typename MetricField<D>::Sample sample;
  std::array<SymMat<D>, D> log_metric_gradient;
};
template <int D>
std::vector<MidpointInput<D>> sampled_midpoints(const EdgeCase<D>& c) {
  const Mesh<D>& mesh = c.field.back_mesh();
  std::vector<MidpointInput<D>> inputs;
  for (std::size_t e = 0; e < c.edges.size(); e += c.edges.size() / 1024) {
    const auto& edge = c.edges[e];
    const Vec<D> a = mesh.vertex(edge[0]), b = mesh.vertex(edge[1]), node = 0.5 * (a + b);
    const auto sample = c.field.sample(node, c.vertex_element[static_cast<std::size_t>(edge[0])]);
    inputs.push_back(
        {EdgeLengthFunction<D>(a, b, c.field.vertex_log_metric(edge[0]), c.field.vertex_log_metric(edge[1]), default_optimizer_rule()),
         node, (1 / norm(b - a)) * (b - a), sample, c.field.log_metric_gradient(sample.where.element)});
  }
  return inputs;
}

template <int D>
void BM_OptimizeMeshEdges(benchmark::State& state) {
  const EdgeCase<D>& c = edge_case<D>();
  const Mesh<D>& mesh = c.field.back_mesh();
  // One benchmark iteration optimizes every edge: each run sees the same edges, whatever its length.
  double iterations = 0, evaluations = 0;
  std::vector<EdgeEndpoint<D>> endpoints(static_cast<std::size_t>(mesh.vertex_count()));
  for (auto _ : state) {
    // The vertices' metrics, once per vertex as a caller curving a whole mesh makes them: part of the cost.
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      endpoints[static_cast<std::size_t>(v)] = edge_endpoint(mesh.vertex(v), c.field.vertex_log_metric(v));
    for (const auto& edge : c.edges) {
      const EdgeEndpoint<D>& a = endpoints[static_cast<std::size_t>(edge[0])];
      const EdgeEndpoint<D>& b = endpoints[static_cast<std::size_t>(edge[1])];
      auto result = optimize_edge_length<D>(c.field, a, b, 0.5 * (a.position + b.position),
                                            c.vertex_element[static_cast<std::size_t>(edge[0])]);
      benchmark::DoNotOptimize(result);
      iterations += result.iterations;
      evaluations += result.evaluations;
    }
  }
  const double edges = static_cast<double>(state.iterations()) * static_cast<double>(c.edges.size());
  state.SetItemsProcessed(static_cast<std::int64_t>(edges));
  state.counters["iterations/edge"] = iterations / edges;
  state.counters["evaluations/edge"] = evaluations / edges;
}
BENCHMARK_TEMPLATE(BM_OptimizeMeshEdges, 2);
BENCHMARK_TEMPLATE(BM_OptimizeMeshEdges, 3);

// Points a small step away from an element's centroid, localized from that element: the walk of one
// optimizer iterate.
template <int D>
void BM_LocalizeFromNearHint(benchmark::State& state) {
  const EdgeCase<D>& c = edge_case<D>();
  const PointLocator<D>& locator = c.field.locator();
  const Index elements = c.field.back_mesh().element_count();
  Index element = 0;
  for (auto _ : state) {
    const SimplexPoints<D> corners = locator.element_points(element);
    Vec<D> point = 0.6 * corners[0];
    for (int i = 1; i <= D; ++i) point += (0.4 / D) * corners[i];
    benchmark::DoNotOptimize(c.field.sample(point, element));
    element = (element + 7919) % elements;  // a stride that leaves the cache, as edges of a real mesh do
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_LocalizeFromNearHint, 2);
BENCHMARK_TEMPLATE(BM_LocalizeFromNearHint, 3);

// Points just outside boundary faces (1% of the element's height beyond the face, at varied spots of the face:
// its centroid, near a corner, near an edge), localized from the element of that face: the trial points of
// boundary edges, which land just outside a convex back mesh and take the closest-element rule.
template <int D>
void BM_LocalizeOutside(benchmark::State& state) {
  const EdgeCase<D>& c = edge_case<D>();
  const PointLocator<D>& locator = c.field.locator();
  const Mesh<D>& mesh = c.field.back_mesh();
  struct Query {
    Vec<D> point;
    Index hint;
  };
  std::vector<Query> queries;
  const std::array<std::array<double, D>, 3> spots = [] {
    std::array<std::array<double, D>, 3> s{};
    for (int i = 0; i < D; ++i) {
      s[0][i] = 1.0 / D;                             // centroid
      s[1][i] = i == 0 ? 0.9 : 0.1 / (D - 1);        // near a corner
      s[2][i] = i == D - 1 ? 0.02 : 0.98 / (D - 1);  // near an edge (in 2D, near the other corner)
    }
    return s;
  }();
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face) {
      if (mesh.neighbor(k, face) != kNoIndex) continue;
      const SimplexPoints<D> corners = locator.element_points(k);
      const auto& spot = spots[queries.size() % spots.size()];
      Vec<D> on_face{};
      for (int i = 0; i < D; ++i) on_face += spot[i] * corners[face_vertices<D>(face)[i]];
      queries.push_back({on_face - 0.01 * (corners[face] - on_face), k});
    }
  std::size_t next = 0;
  for (auto _ : state) {
    const Query& query = queries[next];
    benchmark::DoNotOptimize(locator.localize(query.point, query.hint));
    next = (next + 7919) % queries.size();  // a stride that leaves the cache
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_LocalizeOutside, 2);
BENCHMARK_TEMPLATE(BM_LocalizeOutside, 3);

template <int D>
void BM_ExpFrechetConstruction(benchmark::State& state) {
  const EdgeCase<D>& c = edge_case<D>();
  const Index vertices = c.field.back_mesh().vertex_count();
  Index vertex = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ExpFrechet<D>(c.field.vertex_log_metric(vertex)));
    vertex = (vertex + 1) % vertices;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_ExpFrechetConstruction, 2);
BENCHMARK_TEMPLATE(BM_ExpFrechetConstruction, 3);

// One evaluation of ℓ at the straight midpoint of mesh edges, back-mesh sample and gradient precomputed. Each
// visit of an edge alternates between two log-metrics at the node, so that no evaluation reuses the
// eigen-decompositions of the previous one at the same point.
template <int D>
void BM_EdgeLengthEvaluate(benchmark::State& state) {
  using Order = typename EdgeLengthFunction<D>::Order;
  const auto order = static_cast<Order>(state.range(0));
  const std::vector<MidpointInput<D>> inputs = sampled_midpoints(edge_case<D>());
  const SymMat<D> shift = 1e-3 * SymMat<D>::identity();
  std::size_t next = 0, visit = 0;
  for (auto _ : state) {
    const MidpointInput<D>& input = inputs[next];
    benchmark::DoNotOptimize(input.function.evaluate(input.node, visit % 2 == 0 ? input.sample.log_metric : input.sample.log_metric + shift,
                                                     input.log_metric_gradient, order));
    next = (next + 1) % inputs.size();
    if (next == 0) ++visit;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_EdgeLengthEvaluate, 2)->DenseRange(0, 2)->ArgName("order");
BENCHMARK_TEMPLATE(BM_EdgeLengthEvaluate, 3)->DenseRange(0, 2)->ArgName("order");

// The kink analysis at the straight midpoint of mesh edges (on back-mesh edges: the ring of sectors in 3D),
// the gradient parts precomputed.
template <int D>
void BM_KinkDescent(benchmark::State& state) {
  const EdgeCase<D>& c = edge_case<D>();
  struct Input {
    Localization<D> where;
    Vec<D> direction;
    EdgeLengthValue<D> value;
  };
  std::vector<Input> inputs;
  for (const MidpointInput<D>& m : sampled_midpoints(c))
    inputs.push_back({m.sample.where, m.edge_direction,
                      m.function.evaluate(m.node, m.sample.log_metric, m.log_metric_gradient, EdgeLengthFunction<D>::Order::kGradient)});
  std::size_t next = 0;
  for (auto _ : state) {
    const Input& input = inputs[next];
    benchmark::DoNotOptimize(steepest_descent_on_kink(c.field, input.where, input.direction, input.value));
    next = (next + 1) % inputs.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_KinkDescent, 2);
BENCHMARK_TEMPLATE(BM_KinkDescent, 3);

// The curvature of ℓ along one direction at the point of the last evaluation (a gradient there: its
// decompositions are reused), as for a step along the steepest descent of a kink.
template <int D>
void BM_EdgeLengthCurvature(benchmark::State& state) {
  struct Input {
    MidpointInput<D> at;
    Vec<D> direction;
    SymMat<D> log_metric_derivative;
    EdgeLengthScratch<D> scratch;
  };
  std::vector<Input> inputs;
  for (MidpointInput<D>& m : sampled_midpoints(edge_case<D>())) {
    const Vec<D> direction = orthonormal_complement(m.edge_direction)[0];  // in the bisector plane
    SymMat<D> derivative;
    for (int i = 0; i < D; ++i) derivative += direction[i] * m.log_metric_gradient[i];
    inputs.push_back({m, direction, derivative, {}});
  }
  for (Input& input : inputs)  // in place: a scratch serves the function it was filled by
    input.at.function.evaluate(input.at.node, input.at.sample.log_metric, input.at.log_metric_gradient,
                               EdgeLengthFunction<D>::Order::kGradient, input.scratch);
  std::size_t next = 0;
  for (auto _ : state) {
    Input& input = inputs[next];
    benchmark::DoNotOptimize(input.at.function.curvature(input.at.node, input.at.sample.log_metric, input.direction,
                                                         input.log_metric_derivative, input.scratch));
    next = (next + 1) % inputs.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_EdgeLengthCurvature, 2);
BENCHMARK_TEMPLATE(BM_EdgeLengthCurvature, 3);

template <int D>
void BM_LogMetricGradient(benchmark::State& state) {
  const EdgeCase<D>& c = edge_case<D>();
  const Index elements = c.field.back_mesh().element_count();
  Index element = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.field.log_metric_gradient(element));
    element = (element + 7919) % elements;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_LogMetricGradient, 2);
BENCHMARK_TEMPLATE(BM_LogMetricGradient, 3);

}  // namespace
}  // namespace hocav
