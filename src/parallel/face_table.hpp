// The faces of a set of elements by their sorted vertices, with the elements that have each: the
// neighbours of a mesh part's elements without its topology (docs/distributed.md §Migration).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>

#include "mesh/mesh.hpp"

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

// A face's or facet's vertices, sorted.
template <int D>
FaceKey<D> sorted_key(FaceKey<D> key) {
  std::sort(key.begin(), key.end());
  return key;
}

template <int D>
FaceKey<D> face_key(const typename Mesh<D>::Element& element, int face) {
  FaceKey<D> key{};
  for (int i = 0; i < D; ++i) key[i] = element[face_vertices<D>(face)[i]];
  return sorted_key<D>(key);
}

// The elements (by position) that have a face: the first, and the second when two have it.
struct FaceElements {
  Index first = kNoIndex, second = kNoIndex;
  bool shared() const { return second != kNoIndex; }
};

template <int D>
using FaceTable = std::unordered_map<FaceKey<D>, FaceElements, FaceKeyHash<D>>;

template <int D>
FaceTable<D> face_table(std::span<const typename Mesh<D>::Element> elements) {
  FaceTable<D> faces;
  faces.reserve(elements.size() * (D + 1) / 2 + 1);
  for (std::size_t k = 0; k < elements.size(); ++k)
    for (int face = 0; face <= D; ++face) {
      FaceElements& found = faces[face_key<D>(elements[k], face)];
      (found.first == kNoIndex ? found.first : found.second) = static_cast<Index>(k);
    }
  return faces;
}

}  // namespace hocav
