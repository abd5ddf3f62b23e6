#include "parallel/part_measures.hpp"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "base/thread_pool.hpp"
#include "bezier/mesh_quality.hpp"
#include "report/curving_report.hpp"

namespace hocav {

template <int D>
std::vector<std::array<Index, 2>> interface_edges_by_global_ends(const MeshPart<D>& part) {
  std::vector<std::array<Index, 2>> edges;
  for (std::uint64_t key : interface_edge_keys(part.mesh)) {
    // Mesh::edge_key holds the lower end in the high 32 bits.
    const Index a = part.global_ids[static_cast<Index>(key >> 32)], b = part.global_ids[static_cast<Index>(key & 0xffffffffu)];
    edges.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

template <int D>
void apply_node_updates(MeshPart<D>& part, std::span<const NodeUpdate<D>> updates) {
  Mesh<D>& mesh = part.mesh;
  if (updates.empty()) return;
  const std::unordered_map<Index, Index> local = local_ids_of(part);
  const auto local_of = [&](Index g) {
    const auto found = local.find(g);
    return found == local.end() ? kNoIndex : found->second;
  };
  for (const NodeUpdate<D>& update : updates) {
    const Index a = local_of(update.ends[0]), b = local_of(update.ends[1]);
    if (const Index e = a == kNoIndex || b == kNoIndex ? kNoIndex : mesh.find_edge(a, b); e != kNoIndex) mesh.edge_node(e) = update.node;
  }
}

template <int D>
std::vector<std::vector<NodeUpdate<D>>> node_updates_by_source(const MeshPart<D>& part, std::span<const int> source, int processes) {
  const Mesh<D>& mesh = part.mesh;
  const std::unordered_set<std::uint64_t> frozen = interface_edge_keys(mesh);
  std::vector<std::pair<int, Index>> held;  // (process, edge), each once
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int e = 0; e < Simplex<D>::kEdges; ++e) held.emplace_back(source[static_cast<std::size_t>(k)], mesh.element_edge(k, e));
  std::sort(held.begin(), held.end());
  held.erase(std::unique(held.begin(), held.end()), held.end());
  std::vector<std::vector<NodeUpdate<D>>> out(static_cast<std::size_t>(processes));
  for (const auto& [to, edge] : held) {
    const auto& ends = mesh.edge_vertices(edge);
    if (frozen.contains(Mesh<D>::edge_key(ends[0], ends[1]))) continue;
    out[static_cast<std::size_t>(to)].push_back({{part.global_ids[ends[0]], part.global_ids[ends[1]]}, mesh.edge_node(edge)});
  }
  return out;
}

template <int D>
PartMeasures measure_part(const MeshPart<D>& part, const MetricField<D>& field, const std::vector<char>& on_boundary,
                          std::span<const std::array<Index, 2>> measured_elsewhere, int threads) {
  const Mesh<D>& mesh = part.mesh;
  if (mesh.element_count() == 0) return {};
  std::unordered_set<std::uint64_t> skipped;
  for (const auto& [a, b] : measured_elsewhere) skipped.insert(global_edge_key({a, b}));
  std::vector<Index> edges;  // the edges this part measures, in order
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    const auto& [a, b] = mesh.edge_vertices(e);
    if (a == kNoIndex || (on_boundary[a] && on_boundary[b])) continue;
    if (!skipped.contains(global_edge_key({part.global_ids[a], part.global_ids[b]}))) edges.push_back(e);
  }
  PartMeasures measures;
  measures.elements = mesh_jacobian_quality(mesh, kReportedRefinement, threads);
  std::vector<EdgeGain> gains(edges.size());
  ThreadPool pool(std::max(1, threads));
  run_chunked(pool, edges.size(), kMeasuredChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) gains[i] = edge_gain(mesh, field, edges[i]);
  });
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto& [a, b] = mesh.edge_vertices(edges[i]);
    if (!gains[i].sampled_inside) {
      measures.deferred.push_back({part.global_ids[a], part.global_ids[b]});
      measures.deferred_in_part.push_back(gains[i].value);
    } else
      measures.gains.push_back(gains[i].value);
  }
  return measures;
}

#define HOCAV_INSTANTIATE(D)                                                                                              \
  template std::vector<std::array<Index, 2>> interface_edges_by_global_ends(const MeshPart<D>&);                          \
  template void apply_node_updates(MeshPart<D>&, std::span<const NodeUpdate<D>>);                                         \
  template std::vector<std::vector<NodeUpdate<D>>> node_updates_by_source(const MeshPart<D>&, std::span<const int>, int); \
  template PartMeasures measure_part(const MeshPart<D>&, const MetricField<D>&, const std::vector<char>&,                 \
                                     std::span<const std::array<Index, 2>>, int);
HOCAV_INSTANTIATE(2)
HOCAV_INSTANTIATE(3)
#undef HOCAV_INSTANTIATE

}  // namespace hocav
