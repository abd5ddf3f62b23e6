#include "adapt/reinsertion_curving.hpp"

#include <chrono>

#include "base/error.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {

template <int D>
std::vector<Index> volume_vertices(const Mesh<D>& mesh) {
  std::vector<bool> on_boundary(static_cast<std::size_t>(mesh.vertex_count()), false);
  for (const auto& facet : mesh.facets())
    for (Index v : facet) on_boundary[v] = true;
  std::vector<Index> vertices;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (!on_boundary[v] && mesh.vertex_element(v) != kNoIndex) vertices.push_back(v);
  return vertices;
}

template <int D>
ReinsertionResult curve_by_reinsertion(Mesh<D>& mesh, const MetricField<D>& field, BoundaryNodeSource<D>* boundary,
                                       const ReinsertionOptions& options) {
  if (field.back_mesh().vertex_count() != mesh.vertex_count())
    throw Error("curving: the metric's back mesh has " + std::to_string(field.back_mesh().vertex_count()) +
                " vertices, the mesh " + std::to_string(mesh.vertex_count()));
  if (!mesh.has_topology()) mesh.build_topology();
  if (!mesh.is_p2()) mesh.make_p2();

  // Front vertices start as the back mesh's vertices: same metrics, and the same element ids
  // give each vertex a back element to start its walks from.
  std::vector<SymMat<D>> log_metrics(static_cast<std::size_t>(mesh.vertex_count()));
  std::vector<Index> hints(static_cast<std::size_t>(mesh.vertex_count()));
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    log_metrics[v] = field.vertex_log_metric(v);
    hints[v] = field.back_mesh().vertex_element(v);
  }
  P2CavityOperator<D> cavity_operator(field, log_metrics, hints, boundary, options.cavity);

  ReinsertionResult result;
  const std::vector<Index> vertices = volume_vertices(mesh);
  const auto start = std::chrono::steady_clock::now();
  std::vector<Index> ball;
  const double total = double(vertices.size()) * options.passes;
  const std::size_t report_every = std::max<std::size_t>(1, vertices.size() / 50);
  for (int pass = 0; pass < options.passes; ++pass)
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      collect_ball(mesh, vertices[i], ball);
      cavity_operator.apply(mesh, ball, vertices[i]);
      ++result.vertices_reinserted;
      if (options.progress && i % report_every == 0) options.progress((pass * double(vertices.size()) + static_cast<double>(i)) / total);
    }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.counters = cavity_operator.counters();
  mesh.compact_edges();
  return result;
}

template std::vector<Index> volume_vertices(const Mesh<2>&);
template std::vector<Index> volume_vertices(const Mesh<3>&);
template ReinsertionResult curve_by_reinsertion(Mesh<2>&, const MetricField<2>&, BoundaryNodeSource<2>*,
                                                const ReinsertionOptions&);
template ReinsertionResult curve_by_reinsertion(Mesh<3>&, const MetricField<3>&, BoundaryNodeSource<3>*,
                                                const ReinsertionOptions&);

}  // namespace hocav
