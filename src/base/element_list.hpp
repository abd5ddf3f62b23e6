// Membership in a list of element ids that is usually short (a ball, a cavity: a scan, as
// small_set_holds) but may grow long (a Delaunay cavity spread over a region, or the ball of a
// distributed part's frozen interface vertex, thousands of elements): past kScannedIds ids, a hash
// set of them too, so that growing or walking such a list stays linear in its size.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "base/index_hash_map.hpp"
#include "base/small_set.hpp"

namespace hocav {

class ElementList {
 public:
  // Ids added through push_back go into `ids` too.
  explicit ElementList(std::vector<Index>& ids) : ids_(ids), hashed_(hashed_when_long(ids)) {}
  bool holds(Index k) const { return hashed_ ? hashed_->find(static_cast<std::uint64_t>(k)) != kNoIndex : small_set_holds(ids_, k); }
  void push_back(Index k) {
    ids_.push_back(k);
    if (hashed_)
      hashed_->insert(static_cast<std::uint64_t>(k), 0);
    else if (ids_.size() > kScannedIds)
      hashed_ = hashed_when_long(ids_);
  }

 private:
  static constexpr std::size_t kScannedIds = 64;
  // (Made whole and then moved in, not emplaced: GCC 12's sanitizer build took the emplace's reset of
  // the member it had just constructed empty for a read of uninitialized memory.)
  static std::optional<IndexHashMap> hashed_when_long(const std::vector<Index>& ids) {
    if (ids.size() <= kScannedIds) return std::nullopt;
    IndexHashMap hashed(2 * ids.size());
    for (Index k : ids) hashed.insert(static_cast<std::uint64_t>(k), 0);
    return hashed;
  }
  std::vector<Index>& ids_;
  std::optional<IndexHashMap> hashed_;  // none while the list is short (no allocation)
};

}  // namespace hocav
