#include "parallel/distinct_ids.hpp"

#include <cstdint>
#include <unordered_set>

#include "parallel/communicator.hpp"

namespace hocav {

namespace {

template <class Id>
Index distinct_count_of(const std::vector<Id>& ids) {
  std::vector<std::vector<Id>> outgoing(static_cast<std::size_t>(process_count()));
  for (Id id : ids) outgoing[static_cast<std::size_t>(static_cast<std::uint64_t>(id) % outgoing.size())].push_back(id);
  const std::vector<Id> arrived = exchange_values_joined(outgoing);
  return sum_over_processes(static_cast<Index>(std::unordered_set<Id>(arrived.begin(), arrived.end()).size()));
}

}  // namespace

Index distinct_count(const std::vector<Index>& ids) { return distinct_count_of(ids); }
Index distinct_count(const std::vector<std::uint64_t>& keys) { return distinct_count_of(keys); }

}  // namespace hocav
