// Values asked by global vertex id of the processes that hold them: each process holds a run of
// consecutive ids (rank 0 all of them, as a scatter from rank 0 has it, or the run of a file each
// process read, as a mesh read in pieces has it).
#pragma once

#include <span>
#include <vector>

#include "base/index.hpp"
#include "geom/sym_mat.hpp"
#include "parallel/communicator.hpp"

namespace hocav {

// Collective: every process's run of held ids, [first, first + count); which process holds an id.
class HeldRuns {
 public:
  HeldRuns(Index held_first, Index held_count);
  // Throws Error for an id that no run holds.
  int holder(Index id) const;

 private:
  struct Run {
    Index first, end;
    int process;
  };
  std::vector<Run> starts_;  // the non-empty runs, in order of first
};

// Collective: the value of each of `ids`, asked of the process `holder(id)` names, which answers
// `answer(id)` (per process, in the order asked). `bytes_sent` grows by what this process sent to
// others.
template <typename T, typename Holder, typename Answer>
std::vector<T> values_asked_of(std::span<const Index> ids, const Holder& holder, const Answer& answer, long long& bytes_sent) {
  const auto count = static_cast<std::size_t>(process_count()), self = static_cast<std::size_t>(process_rank());
  std::vector<std::vector<Index>> asked(count);
  std::vector<int> holder_of(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    holder_of[i] = holder(ids[i]);
    asked[static_cast<std::size_t>(holder_of[i])].push_back(ids[i]);
  }
  const std::vector<std::vector<Index>> arrived = exchange_values(asked);
  std::vector<std::vector<T>> answers(count);
  for (std::size_t p = 0; p < count; ++p) {
    for (Index id : arrived[p]) answers[p].push_back(answer(id));
    if (p != self) bytes_sent += static_cast<long long>(asked[p].size() * sizeof(Index) + answers[p].size() * sizeof(T));
  }
  const std::vector<std::vector<T>> replies = exchange_values(answers);
  std::vector<std::size_t> next(count, 0);
  std::vector<T> values;
  values.reserve(ids.size());
  for (int p : holder_of) values.push_back(replies[static_cast<std::size_t>(p)][next[static_cast<std::size_t>(p)]++]);
  return values;
}

// Collective. This process holds the values of ids [held_first, held_first + held.size()); returns
// the value of each of `ids`, each asked of the process whose run holds it (throws Error for an id
// that no run holds). `bytes_sent` grows by what this process sent to others.
template <typename T>
std::vector<T> values_by_global_id(std::span<const Index> ids, Index held_first, const std::vector<T>& held, long long& bytes_sent) {
  const HeldRuns runs(held_first, static_cast<Index>(held.size()));
  return values_asked_of<T>(
      ids, [&](Index id) { return runs.holder(id); }, [&](Index id) { return held.at(static_cast<std::size_t>(id - held_first)); },
      bytes_sent);
}

// The same for metrics.
template <int D>
std::vector<SymMat<D>> metrics_by_global_id(std::span<const Index> ids, Index held_first, const std::vector<SymMat<D>>& held,
                                            long long& bytes_sent) {
  return values_by_global_id(ids, held_first, held, bytes_sent);
}

}  // namespace hocav
