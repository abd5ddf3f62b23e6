#include "parallel/metrics_by_global_id.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "base/error.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

// Every process's run of held ids, (first, process), the empty runs left out, in order of first.
class HeldRuns {
 public:
  HeldRuns(Index held_first, Index held_count) {
    const std::vector<std::array<Index, 2>> runs = all_gather_value(std::array<Index, 2>{held_first, held_count});
    for (std::size_t p = 0; p < runs.size(); ++p)
      if (runs[p][1] > 0) starts_.push_back({runs[p][0], runs[p][0] + runs[p][1], static_cast<int>(p)});
    std::sort(starts_.begin(), starts_.end(), [](const Run& a, const Run& b) { return a.first < b.first; });
  }

  int holder(Index id) const {
    auto after = std::upper_bound(starts_.begin(), starts_.end(), id, [](Index value, const Run& run) { return value < run.first; });
    if (after == starts_.begin() || id >= std::prev(after)->end)
      throw Error("metrics by vertex id: no process holds the metric of vertex " + std::to_string(static_cast<long long>(id) + 1));
    return std::prev(after)->process;
  }

 private:
  struct Run {
    Index first, end;
    int process;
  };
  std::vector<Run> starts_;
};

}  // namespace

template <int D>
std::vector<SymMat<D>> metrics_by_global_id(std::span<const Index> ids, Index held_first, const std::vector<SymMat<D>>& held,
                                            long long& bytes_sent) {
  const HeldRuns runs(held_first, static_cast<Index>(held.size()));
  const auto count = static_cast<std::size_t>(process_count()), self = static_cast<std::size_t>(process_rank());
  std::vector<std::vector<Index>> asked(count);
  std::vector<int> holder_of(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    holder_of[i] = runs.holder(ids[i]);
    asked[static_cast<std::size_t>(holder_of[i])].push_back(ids[i]);
  }
  const std::vector<std::vector<Index>> arrived = exchange_values(asked);
  std::vector<std::vector<SymMat<D>>> answers(count);
  for (std::size_t p = 0; p < count; ++p) {
    for (Index id : arrived[p]) answers[p].push_back(held.at(static_cast<std::size_t>(id - held_first)));
    if (p != self) bytes_sent += static_cast<long long>(asked[p].size() * sizeof(Index) + answers[p].size() * sizeof(SymMat<D>));
  }
  const std::vector<std::vector<SymMat<D>>> replies = exchange_values(answers);
  std::vector<std::size_t> next(count, 0);
  std::vector<SymMat<D>> metrics;
  metrics.reserve(ids.size());
  for (int p : holder_of) metrics.push_back(replies[static_cast<std::size_t>(p)][next[static_cast<std::size_t>(p)]++]);
  return metrics;
}

template std::vector<SymMat<2>> metrics_by_global_id(std::span<const Index>, Index, const std::vector<SymMat<2>>&, long long&);
template std::vector<SymMat<3>> metrics_by_global_id(std::span<const Index>, Index, const std::vector<SymMat<3>>&, long long&);

}  // namespace hocav
