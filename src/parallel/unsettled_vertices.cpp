#include "parallel/unsettled_vertices.hpp"

#include "adapt/metric_measures.hpp"

namespace hocav {

template <int D>
std::vector<char> unsettled_vertex_flags(const Mesh<D>& mesh, const AdaptationMetric<D>& metric, int threads) {
  const std::vector<SymMat<D>> metrics = metrics_at_vertices(mesh, metric, threads);
  std::vector<char> flags(static_cast<std::size_t>(mesh.vertex_count()), 0);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& element = mesh.element(k);
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j < i; ++j) {
        const Index a = element[i], b = element[j];
        if (metric_edge_length<D>(mesh.vertex(a), mesh.vertex(b), metrics[a], metrics[b]) > kUnsettledEdgeLength) flags[a] = flags[b] = 1;
      }
  }
  return flags;
}

template std::vector<char> unsettled_vertex_flags(const Mesh<2>&, const AdaptationMetric<2>&, int);
template std::vector<char> unsettled_vertex_flags(const Mesh<3>&, const AdaptationMetric<3>&, int);

}  // namespace hocav
