// The candidate edges of splits and collapses (adaptation_operations.hpp, edges_beyond).
#include <algorithm>
#include <array>

#include "adapt/adaptation_operations.hpp"

namespace hocav {

template <int D>
std::vector<EdgeCandidate> edges_beyond(const AdaptationMesh<D>& am, double bound, bool longer, ThreadPool& pool) {
  // The edges (a < b) of the elements with a recently changed vertex, bucketed by a (a counting
  // sort: the whole mesh's edges in the first passes), then each bucket sorted and made unique.
  const Mesh<D>& mesh = am.mesh();
  const auto for_each_changed_edge = [&](auto visit) {
    for (const auto& element : mesh.elements()) {
      std::array<bool, D + 1> changed;
      for (int i = 0; i <= D; ++i) changed[i] = am.changed_recently(element[i]);
      for (int i = 0; i <= D; ++i)
        for (int j = 0; j < i; ++j)
          if (changed[i] || changed[j]) visit(std::min(element[i], element[j]), std::max(element[i], element[j]));
    }
  };
  std::vector<Index> first(static_cast<std::size_t>(mesh.vertex_count()) + 1, 0);
  for_each_changed_edge([&](Index a, Index) { ++first[static_cast<std::size_t>(a) + 1]; });
  for (std::size_t v = 1; v < first.size(); ++v) first[v] += first[v - 1];
  std::vector<Index> ends(static_cast<std::size_t>(first.back())), fill(first.begin(), first.end() - 1);
  for_each_changed_edge([&](Index a, Index b) { ends[static_cast<std::size_t>(fill[a]++)] = b; });
  // Each bucket's sort and lengths on the pool's threads, in chunks of vertices gathered in order.
  constexpr std::size_t kChunk = 2048;
  std::vector<EdgeCandidate> candidates = joined(results_by_chunk<std::vector<EdgeCandidate>>(
      pool, static_cast<std::size_t>(mesh.vertex_count()), kChunk,
      [&](std::size_t begin, std::size_t end, std::vector<EdgeCandidate>& out) {
        for (auto a = static_cast<Index>(begin); a < static_cast<Index>(end); ++a) {
          const auto bucket_begin = ends.begin() + first[a], bucket_end = ends.begin() + first[a + 1];
          std::sort(bucket_begin, bucket_end);
          for (auto b = bucket_begin; b != bucket_end; ++b)
            if (b == bucket_begin || *b != *(b - 1))
              if (const double length = am.edge_length(a, *b); longer ? length > bound : length < bound) out.push_back({length, a, *b});
        }
      }));
  std::sort(candidates.begin(), candidates.end(), [longer](const EdgeCandidate& x, const EdgeCandidate& y) {
    if (x.length != y.length) return longer ? x.length > y.length : x.length < y.length;
    return std::pair(x.a, x.b) < std::pair(y.a, y.b);
  });
  return candidates;
}

template std::vector<EdgeCandidate> edges_beyond(const AdaptationMesh<2>&, double, bool, ThreadPool&);
template std::vector<EdgeCandidate> edges_beyond(const AdaptationMesh<3>&, double, bool, ThreadPool&);

}  // namespace hocav
