// A face of a distributed mesh by its sorted global vertex ids, and its hash: how the two sides of an
// interface face meet at one process (docs/distributed.md §Partitioning).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "base/index.hpp"

namespace hocav {

template <int D>
using FaceKey = std::array<Index, D>;

template <int D>
struct FaceKeyHash {
  std::size_t operator()(const FaceKey<D>& key) const {
    std::uint64_t h = 0;
    for (Index v : key) h = (h ^ static_cast<std::uint32_t>(v)) * 0x100000001b3ULL;  // FNV-1a's prime
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

// The process where the sides of a face (by its sorted global ids) meet, of `process_count`.
template <int D>
int meeting_process(const FaceKey<D>& key, int process_count) {
  return static_cast<int>(FaceKeyHash<D>{}(key) % static_cast<std::size_t>(process_count));
}

// The process where the copies of the vertex with global id `id` meet, of `process_count`.
inline int vertex_meeting_process(Index id, int process_count) { return static_cast<int>(id % process_count); }

template <int D>
FaceKey<D> sorted_key(FaceKey<D> key) {
  std::sort(key.begin(), key.end());
  return key;
}

}  // namespace hocav
