#include "base/digest_memo.hpp"

namespace hocav {
namespace {

constexpr std::size_t kFirstTableSize = 256;

// The slot of `key` in `keys`, or the empty slot where it would go.
std::size_t slot_of(const std::vector<Digest::Value>& keys, const Digest::Value& key) {
  const std::size_t mask = keys.size() - 1;
  std::size_t slot = static_cast<std::size_t>(key.second) & mask;
  while (keys[slot].first != 0 && keys[slot] != key) slot = (slot + 1) & mask;
  return slot;
}

}  // namespace

std::optional<double> DigestMemo::find(const Digest::Value& key) const {
  Shard& shard = shard_of(key);
  const std::lock_guard lock(shard.mutex);
  if (shard.keys.empty()) return std::nullopt;
  const std::size_t slot = slot_of(shard.keys, key);
  if (shard.keys[slot].first == 0) return std::nullopt;
  return shard.values[slot];
}

void DigestMemo::remember(const Digest::Value& key, double value) {
  Shard& shard = shard_of(key);
  const std::lock_guard lock(shard.mutex);
  if (2 * (shard.used + 1) > shard.keys.size()) {  // grow: every key again in a table twice the size
    std::vector<Digest::Value> keys(std::max(kFirstTableSize, 2 * shard.keys.size()));
    std::vector<double> values(keys.size());
    for (std::size_t old = 0; old < shard.keys.size(); ++old)
      if (shard.keys[old].first != 0) {
        const std::size_t slot = slot_of(keys, shard.keys[old]);
        keys[slot] = shard.keys[old];
        values[slot] = shard.values[old];
      }
    shard.keys = std::move(keys);
    shard.values = std::move(values);
  }
  const std::size_t slot = slot_of(shard.keys, key);
  if (shard.keys[slot].first != 0) return;  // known already
  shard.keys[slot] = key;
  shard.values[slot] = value;
  ++shard.used;
}

}  // namespace hocav
