// The mesh operations expressed as cavities (the paper's Fig. 8), each one plan + commit of the
// cavity operator:
//   reinsertion  the ball of v, v reinserted (the P2 curving pass uses it on every volume vertex)
//   collapse     the ball of a, its neighbour b reinserted (a disappears)
//   swap         the shell of edge (a, b), a vertex p of the shell's boundary reinserted
//   insertion    a new vertex at x with its Delaunay cavity in a given metric, or a given cavity
// Each returns the operator's verdict; on anything but kAccepted the mesh is unchanged.
#pragma once

#include <span>
#include <vector>

#include "cavity/cavity_operator.hpp"
#include "geom/sym_mat.hpp"

namespace hocav {

// Scratch shared by the operations (reuse one per thread: no allocation once warm).
template <int D>
struct CavityWorkspace {
  CavityOperator<D> cavity_operator;
  std::vector<Index> cavity;
  std::vector<Index> refused;  // grow_delaunay_cavity's elements outside the circumsphere test
};

template <int D>
CavityStatus reinsert_vertex(Mesh<D>& mesh, CavityWorkspace<D>& work, Index v, const CavityOptions& options);

template <int D>
CavityStatus collapse_edge(Mesh<D>& mesh, CavityWorkspace<D>& work, Index removed, Index kept, CavityOptions options);

template <int D>
CavityStatus swap_edge(Mesh<D>& mesh, CavityWorkspace<D>& work, Index a, Index b, Index apex, const CavityOptions& options);

// Grows `cavity` (elements around x) by Bowyer–Watson in the constant metric `metric`: the
// neighbours, through faces that carry no boundary facet, whose circumsphere in the metric contains
// x. `refused` receives the neighbours tested and left out. Reads the mesh only.
template <int D>
void grow_delaunay_cavity(const Mesh<D>& mesh, std::vector<Index>& cavity, std::vector<Index>& refused, const Vec<D>& x,
                          const SymMat<D>& metric);

// Drops from `cavity` the elements past its first `kept` that keep it from being star-shaped from x:
// one with a boundary face that x sees from outside (its star element would be flat or inverted),
// then whatever only that element joined to the first `kept`; until x sees every boundary face of
// the elements past the first `kept` (mmg's correction of a Delaunay cavity in a mesh that is not
// Delaunay). The dropped elements go to `dropped`. Reads the mesh only.
template <int D>
void make_star_shaped(const Mesh<D>& mesh, std::vector<Index>& cavity, std::size_t kept, std::vector<Index>& dropped, const Vec<D>& x);

// Inserts a new vertex at x (found from `hint`, an element near x). The cavity holds the elements,
// connected to the one containing x, whose circumsphere in the constant metric `metric` contains x
// (Bowyer–Watson in the metric space). Returns the new vertex's id through `inserted`.
template <int D>
CavityStatus insert_vertex(Mesh<D>& mesh, CavityWorkspace<D>& work, const Vec<D>& x, Index hint, const SymMat<D>& metric,
                           const CavityOptions& options, Index* inserted = nullptr);

}  // namespace hocav
