#include "adapt/reinsertion_curving.hpp"

#include <chrono>
#include <memory>

#include "adapt/independent_batches.hpp"
#include "base/error.hpp"
#include "base/thread_pool.hpp"
#include "bezier/jacobian_bounds.hpp"
#include "bezier/p2_element.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/boundary_vertices.hpp"
#include "mesh/vertex_graph.hpp"

namespace hocav {
namespace {

// Cavities prepared together. Fixed, so the work does not depend on the thread count.
constexpr std::size_t kCavitiesPerRound = 512;

// Certifies every element of `mesh` (a straight one takes the fast path), counted in `counters`.
template <int D>
bool every_element_above_floor(const Mesh<D>& mesh, double floor, ThreadPool& pool, P2CavityCounters& counters) {
  constexpr Index kElementsPerTask = 4096;
  const Index count = mesh.element_count();
  const auto tasks = static_cast<std::size_t>((count + kElementsPerTask - 1) / kElementsPerTask);
  std::vector<char> above(tasks, 1);
  std::vector<double> seconds(tasks);
  pool.run(tasks, [&](std::size_t task) {
    const auto start = std::chrono::steady_clock::now();
    const Index first = static_cast<Index>(task) * kElementsPerTask, last = std::min(count, first + kElementsPerTask);
    for (Index k = first; k < last; ++k)
      if (!certify_min_normalized_jacobian_above(gather_p2_element(mesh, k), floor)) above[task] = 0;
    seconds[task] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
  counters.elements_certified += count;
  for (double s : seconds) counters.seconds_certify += s;
  return std::all_of(above.begin(), above.end(), [](char a) { return a != 0; });
}

}  // namespace

template <int D>
std::vector<Index> volume_vertices(const Mesh<D>& mesh) {
  const std::vector<bool> on_boundary = boundary_vertex_flags(mesh);
  std::vector<Index> vertices;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (!on_boundary[v] && mesh.vertex_element(v) != kNoIndex) vertices.push_back(v);
  return vertices;
}

template <int D>
ReinsertionResult curve_by_reinsertion(Mesh<D>& mesh, const MetricField<D>& field, BoundaryNodeSource<D>* boundary,
                                       const ReinsertionOptions& options) {
  if (field.back_mesh().vertex_count() != mesh.vertex_count())
    throw Error("curving: the metric's back mesh has " + std::to_string(field.back_mesh().vertex_count()) + " vertices, the mesh " +
                std::to_string(mesh.vertex_count()));
  if (!mesh.has_topology()) mesh.build_topology();
  if (!mesh.is_p2()) mesh.make_p2();
  // The time counts everything from here: the metric at the front vertices, the batches, the passes.
  const auto start = std::chrono::steady_clock::now();

  // Front vertices start as the back mesh's vertices: same metrics, and the same element ids
  // give each vertex a back element to start its walks from.
  std::vector<SymMat<D>> log_metrics(static_cast<std::size_t>(mesh.vertex_count()));
  std::vector<Index> hints(static_cast<std::size_t>(mesh.vertex_count()));
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    log_metrics[v] = field.vertex_log_metric(v);
    hints[v] = field.back_mesh().vertex_element(v);
  }
  ThreadPool pool(std::max(1, options.threads));
  ReinsertionResult result;
  OptimizedEdgeMarks optimized_edges;
  P2CavityOptions cavity_options = options.cavity;
  if (options.reuse_results)
    cavity_options.every_element_above_floor = every_element_above_floor(mesh, cavity_options.jacobian_floor, pool, result.counters);
  std::vector<std::unique_ptr<P2CavityOperator<D>>> operators;
  for (std::size_t i = 0; i < kCavitiesPerRound; ++i)
    operators.push_back(std::make_unique<P2CavityOperator<D>>(field, log_metrics, hints, options.reuse_results ? &optimized_edges : nullptr,
                                                              boundary, cavity_options));
  std::vector<std::vector<Index>> balls(kCavitiesPerRound);
  std::vector<CavityStatus> statuses(kCavitiesPerRound);

  std::vector<Index> vertices = volume_vertices(mesh);
  if (!options.region.empty()) std::erase_if(vertices, [&](Index v) { return !options.region[v]; });
  const auto batches = independent_batches(vertex_graph(mesh), vertices, boundary ? 4 : 3);
  const double total = static_cast<double>(vertices.size()) * options.passes;
  double done = 0, reported = 0;
  for (int pass = 0; pass < options.passes; ++pass)
    for (const auto& batch : batches)
      for (std::size_t first = 0; first < batch.size(); first += kCavitiesPerRound) {
        const std::size_t count = std::min(kCavitiesPerRound, batch.size() - first);
        pool.run(count, [&](std::size_t i) {
          collect_ball(mesh, batch[first + i], balls[i]);
          statuses[i] = operators[i]->prepare(mesh, balls[i], batch[first + i]);
        });
        for (std::size_t i = 0; i < count; ++i)
          if (statuses[i] == CavityStatus::kAccepted) operators[i]->commit(mesh);
        result.vertices_reinserted += static_cast<Index>(count);
        done += static_cast<double>(count);
        if (options.progress && done - reported >= 0.02 * total) {
          options.progress(done / total);
          reported = done;
        }
      }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& cavity_operator : operators) result.counters += cavity_operator->counters();
  mesh.compact_edges();
  return result;
}

template std::vector<Index> volume_vertices(const Mesh<2>&);
template std::vector<Index> volume_vertices(const Mesh<3>&);
template ReinsertionResult curve_by_reinsertion(Mesh<2>&, const MetricField<2>&, BoundaryNodeSource<2>*, const ReinsertionOptions&);
template ReinsertionResult curve_by_reinsertion(Mesh<3>&, const MetricField<3>&, BoundaryNodeSource<3>*, const ReinsertionOptions&);

}  // namespace hocav
