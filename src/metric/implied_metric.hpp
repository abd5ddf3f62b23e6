// The natural (implied) metric of a mesh (docs/method.md §10): the metric in which the mesh is a unit mesh.
//
// Element metric: the unique M with eᵀ M e = 1 on the d(d+1)/2 edges e of the element. These are
// d(d+1)/2 linear equations in the d(d+1)/2 entries of M; their solution has the closed form
//   M_K = ½ Σ_{i=0..d} ∇λ_i ∇λ_iᵀ
// (∇λ_i the constant barycentric gradients, docs/method.md §2): for e = P_j − P_k, ∇λ_i·e = δ_ij − δ_ik,
// so eᵀ M_K e = ½ (1 + 1) = 1. It is SPD for every non-flat element, since the ∇λ_i span R^d. If
// K = F(K̂) with F(x) = A x + b and K̂ the regular simplex of unit edges, M_K = (A Aᵀ)⁻¹.
// Vertex metric: the log-Euclidean mean of the metrics of the elements around the vertex, weighted
// by their (straight, absolute) measures: M_v = exp(Σ_K |K| log M_K / Σ_K |K|).
#pragma once

#include <vector>

#include "geom/barycentric.hpp"
#include "geom/sym_mat.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

template <int D>
SymMat<D> element_implied_metric(const SimplexPoints<D>& points);

// What element k gives each of its vertices' metric: its (absolute) measure, and its metric's
// logarithm weighted by it. Throws Error naming the element (as number `number`, 1-based) when it
// is flat.
template <int D>
struct ImpliedShare {
  double weight = 0;
  SymMat<D> weighted_log;

  // A vertex's sum takes its elements' shares one by one (the order decides the last bits).
  ImpliedShare& operator+=(const ImpliedShare& share) {
    weighted_log += share.weighted_log;
    weight += share.weight;
    return *this;
  }
};

template <int D>
ImpliedShare<D> implied_share(const Mesh<D>& mesh, Index k, Index number);

// The vertex metric of the summed shares of its elements.
template <int D>
SymMat<D> implied_vertex_metric(const ImpliedShare<D>& sum);

// One metric per vertex, from the straight (P1) elements. Throws Error naming the element for a
// flat element, and the vertex for a vertex that no element uses.
template <int D>
std::vector<SymMat<D>> implied_metric_at_vertices(const Mesh<D>& mesh);

}  // namespace hocav
