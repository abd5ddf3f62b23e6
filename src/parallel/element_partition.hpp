// The partition of a mesh's elements among processes (docs/distributed.md §Partitioning): the dual
// graph (elements, joined across their shared faces) with each element's load as its weight and
// heavier faces near the last interfaces, cut by Scotch into parts of balanced load.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

// A graph in compressed rows, with integer weights on its vertices and edges.
struct WeightedGraph {
  std::vector<std::int64_t> offsets;  // vertex i's neighbours are neighbours[offsets[i] .. offsets[i + 1])
  std::vector<std::int64_t> neighbours, vertex_weights, edge_weights;
};

// The loads as integer weights, in the same proportions: scaled so that loads summing to `total`
// (over every process of a distributed graph) weigh less than 1e9, and Scotch's sums never overflow.
std::vector<std::int64_t> integer_loads(std::span<const double> loads, double total);

// The largest load imbalance a part may have, in Scotch's and PT-Scotch's partitions.
constexpr double kPartImbalance = 0.05;

// A face joining two elements that both touch a vertex to keep inside the parts (of the last
// interfaces, or at an edge their loops left unadapted) weighs this many ordinary faces: the
// partitioner then cuts elsewhere (docs/distributed.md §The scheme, step 4).
constexpr std::int64_t kKeptInsideFaceWeight = 100;

// Whether `element` has a vertex marked in `marked` (per vertex; none when it is empty).
template <int D>
bool touches(const typename Mesh<D>::Element& element, std::span<const char> marked) {
  return !marked.empty() && std::any_of(element.begin(), element.end(), [&](Index v) { return marked[v] != 0; });
}

// The dual graph of `mesh` (with topology): element k weighs in proportion to `loads[k]` (at least
// 1); `kept_inside` (per vertex, may be empty) marks the vertices to keep inside parts.
template <int D>
WeightedGraph element_graph(const Mesh<D>& mesh, std::span<const double> loads, std::span<const char> kept_inside);

// The dual graph of the elements marked in `members` (per element), joined across the faces they
// share with other members; graph vertex i is element `elements[i]` (in mesh order), weighing in
// proportion to its `loads` entry (per element of `mesh`), or 1 when `loads` is empty.
template <int D>
WeightedGraph member_graph(const Mesh<D>& mesh, std::span<const char> members, std::span<const double> loads, std::vector<Index>& elements);

// Per element: within `rings` rings of a vertex marked in `marked` (ring 1: the elements holding one).
template <int D>
std::vector<char> elements_near(const Mesh<D>& mesh, std::vector<char> marked, int rings);

// Per element, the label of its nearest labelled vertices within `rings` rings (the smallest when
// several are as near), or kNoLabel beyond them; `labels` per vertex, kNoLabel for none, the others
// non-negative. The elements so labelled are elements_near's.
constexpr int kNoLabel = -1;
template <int D>
std::vector<int> nearest_labels(const Mesh<D>& mesh, std::vector<int> labels, int rings);

// Scotch's partition of `graph` into `part_count` parts of balanced vertex weight and small cut
// weight; the part of each vertex. The same graph and seed give the same parts; seed 0 is Scotch's
// own fixed seed, and another seed makes another partition as good (bench/distributed_draws.py
// measures a distributed run over several).
std::vector<int> partition_graph(const WeightedGraph& graph, int part_count, std::int64_t seed = 0);

}  // namespace hocav
