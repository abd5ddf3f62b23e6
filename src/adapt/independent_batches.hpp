// Batches of vertices whose cavities (their balls) can be prepared at the same time and committed
// one after the other in any order, because no commit touches what another cavity read.
//  - Balls that share no vertex (vertices at least 3 edges apart) suffice when only inner edges
//    change: no element outside a ball is touched.
//  - When boundary edges on the balls' boundaries may change too, an element outside both balls
//    could hold a changed edge of each, and each cavity would certify it with the other's old
//    node: then vertices must be at least 4 edges apart.
#pragma once

#include <span>
#include <vector>

#include "mesh/vertex_graph.hpp"

namespace hocav {

// Greedy colouring of `vertices` (in their given order) so that two vertices of one colour are
// at least `min_distance` edges apart; each colour is one batch, keeping that order. Deterministic.
std::vector<std::vector<Index>> independent_batches(const VertexGraph& graph, std::span<const Index> vertices, int min_distance);

}  // namespace hocav
