// Moves given at some vertices of a mesh (the fixed ones), extended to the others so that the mesh
// deforms smoothly: the harmonic extension of the P1 finite-element Laplacian, which extends a move
// linear in space exactly (docs/adaptation.md §Boundary settling). Only vertices near a moving fixed
// vertex move: within `reach_factor` times its move, by path length along the edges; the others keep
// a zero move.
#pragma once

#include <span>
#include <vector>

#include "mesh/vertex_graph.hpp"

namespace hocav {

template <int D>
struct HarmonicExtension {
  std::vector<Vec<D>> moves;  // per vertex: the given move at fixed vertices, zero outside the reach
  Index free_vertices = 0;    // the vertices solved for
  int iterations = 0;         // of the conjugate gradients, summed over the coordinates
};

// `fixed` and `moves` per vertex of `mesh`; the moves of free vertices are ignored. Solved by
// Jacobi-preconditioned conjugate gradients, serially (the same result for any thread count). Only
// the vertices within reach are visited and given graph rows, so a few moves in a large mesh cost
// little more than their neighbourhoods (and a pass over the elements).
template <int D>
HarmonicExtension<D> harmonic_extension(const Mesh<D>& mesh, std::span<const char> fixed, std::span<const Vec<D>> moves,
                                        double reach_factor);

}  // namespace hocav
