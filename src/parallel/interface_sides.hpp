// The two sides of a distributed mesh's interface faces meeting (docs/distributed.md
// §Partitioning): each process sends a record per side it holds to the process the face's sorted
// global ids hash to, which gives each side the other's record. The distributed graph learns the
// group across a face so, the pieces of a file the element ref across it.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "base/error.hpp"
#include "parallel/communicator.hpp"
#include "parallel/face_key.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// A face of a part (by its local vertex ids) by its sorted global vertex ids.
template <int D>
FaceKey<D> global_key(const MeshPart<D>& part, const FaceKey<D>& local) {
  FaceKey<D> key{};
  for (int i = 0; i < D; ++i) key[i] = part.global_ids[local[i]];
  return sorted_key<D>(key);
}

// Every process at once, `own` its sides (records with a `face`, the sorted global key, and the
// `process` that holds them, trivially copyable): per face of `own`, the record of the side across
// it. Throws Error for a face that has not exactly two sides.
template <int D, typename Side>
std::unordered_map<FaceKey<D>, Side, FaceKeyHash<D>> sides_across(const std::vector<Side>& own) {
  std::vector<std::vector<Side>> outgoing(static_cast<std::size_t>(process_count()));
  for (const Side& side : own) outgoing[meeting_process<D>(side.face, process_count())].push_back(side);
  std::unordered_map<FaceKey<D>, std::vector<Side>, FaceKeyHash<D>> met;
  for (const Side& side : exchange_values_joined(outgoing)) met[side.face].push_back(side);
  std::vector<std::vector<Side>> answers(outgoing.size());
  for (const auto& [face, sides] : met) {
    if (sides.size() != 2) throw Error("distributed mesh: an interface face has " + std::to_string(sides.size()) + " sides, not 2");
    answers[static_cast<std::size_t>(sides[0].process)].push_back(sides[1]);
    answers[static_cast<std::size_t>(sides[1].process)].push_back(sides[0]);
  }
  std::unordered_map<FaceKey<D>, Side, FaceKeyHash<D>> across;
  for (const Side& side : exchange_values_joined(answers)) across.emplace(side.face, side);
  return across;
}

}  // namespace hocav
