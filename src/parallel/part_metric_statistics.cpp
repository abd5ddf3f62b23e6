#include "parallel/part_metric_statistics.hpp"

#include <algorithm>
#include <tuple>

#include "parallel/communicator.hpp"
#include "parallel/face_key.hpp"

namespace hocav {
namespace {

// An edge that several parts may hold, with its length, on its way to where its ends hash to.
struct SharedLength {
  FaceKey<2> key;
  double length;
};

// Per vertex of the part: whether another part may hold it.
template <int D>
std::vector<char> maybe_shared(const MeshPart<D>& part) {
  std::vector<char> shared = interface_vertex_flags(part.mesh);
  for (std::size_t v = 0; v < shared.size() && v < part.pinned.size(); ++v) shared[v] = static_cast<char>(shared[v] || part.pinned[v]);
  return shared;
}

// Adds the lengths of the shared edges that arrived, each edge once (its first arrival in rank order),
// in the order of their keys.
void add_shared_lengths(const std::vector<std::vector<SharedLength>>& arrived, MetricTally& tally) {
  std::vector<std::tuple<FaceKey<2>, std::size_t, std::size_t>> order;  // key, sender, place
  for (std::size_t from = 0; from < arrived.size(); ++from)
    for (std::size_t i = 0; i < arrived[from].size(); ++i) order.emplace_back(arrived[from][i].key, from, i);
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < order.size(); ++i)
    if (i == 0 || std::get<0>(order[i]) != std::get<0>(order[i - 1]))
      tally.add_length(arrived[std::get<1>(order[i])][std::get<2>(order[i])].length);
}

}  // namespace

template <int D>
MetricStatistics distributed_metric_statistics(const MeshPart<D>& part, std::span<const double> vertex_metrics, int threads) {
  const MetricValues values = compute_metric_values(part.mesh, vertex_metrics, threads);
  MetricTally tally;
  for (double anisotropy : values.anisotropies) tally.max_anisotropy = std::max(tally.max_anisotropy, anisotropy);
  for (double quality : values.qualities) tally.add_quality(quality);
  const std::vector<char> shared = maybe_shared(part);
  std::vector<std::vector<SharedLength>> outgoing(static_cast<std::size_t>(process_count()));
  for (std::size_t i = 0; i < values.edges.size(); ++i) {
    const auto [a, b] = values.edges[i];
    if (!shared[a] || !shared[b]) {
      tally.add_length(values.lengths[i]);
      continue;
    }
    const FaceKey<2> key = sorted_key<2>({part.global_ids[a], part.global_ids[b]});
    outgoing[static_cast<std::size_t>(meeting_process<2>(key, process_count()))].push_back({key, values.lengths[i]});
  }
  add_shared_lengths(exchange_values(outgoing), tally);
  MetricTally whole;
  for (const MetricTally& each : all_gather_value(tally)) whole.add(each);
  return whole.statistics();
}

template MetricStatistics distributed_metric_statistics(const MeshPart<2>&, std::span<const double>, int);
template MetricStatistics distributed_metric_statistics(const MeshPart<3>&, std::span<const double>, int);

}  // namespace hocav
