#include "parallel/distinct_ids.hpp"

#include <unordered_set>

#include "parallel/communicator.hpp"

namespace hocav {

Index distinct_count(const std::vector<Index>& ids) {
  std::vector<std::vector<Index>> outgoing(static_cast<std::size_t>(process_count()));
  for (Index id : ids) outgoing[static_cast<std::size_t>(id) % outgoing.size()].push_back(id);
  const std::vector<Index> arrived = exchange_values_joined(outgoing);
  return sum_over_processes(static_cast<Index>(std::unordered_set<Index>(arrived.begin(), arrived.end()).size()));
}

}  // namespace hocav
