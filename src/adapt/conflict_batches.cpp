#include "adapt/conflict_batches.hpp"

#include <bit>

namespace hocav {

namespace {
constexpr std::size_t kMaxBatches = 64;  // one bit each in a key's mask
}

bool ConflictBatches::place(Index item, std::span<const Index> keys) {
  std::uint64_t busy = 0;
  for (Index key : keys) busy |= taken_[static_cast<std::size_t>(key)];
  const auto batch = static_cast<std::size_t>(std::countr_one(busy));
  if (batch == kMaxBatches) {
    overflow_.push_back(item);
    return false;
  }
  for (Index key : keys) {
    std::uint64_t& bits = taken_[static_cast<std::size_t>(key)];
    if (bits == 0) touched_.push_back(key);
    bits |= std::uint64_t{1} << batch;
  }
  if (batch == batches_.size()) batches_.emplace_back();
  batches_[batch].push_back(item);
  return true;
}

void ConflictBatches::clear() {
  for (Index key : touched_) taken_[static_cast<std::size_t>(key)] = 0;
  touched_.clear();
  batches_.clear();
  overflow_.clear();
}

}  // namespace hocav
