// The metric's back mesh in shares, for a distributed run (docs/distributed.md §The back mesh in
// shares): no process but rank 0 holds the whole back mesh. Each holds a home share (the back
// elements of its part of the first partition, with their vertices' log-metrics), and for the part
// it adapts it gathers from every home the back elements near the part (whose boxes meet its region).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "geom/box.hpp"
#include "geom/sym_mat.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// Where a part asks for its metric: a grid of kShareCells cells per axis over its vertices' box
// widened on every side by kShareMargin of its diagonal, the cells its elements' boxes meet marked,
// and their neighbours (a boundary vertex that a split puts on the geometry may lie a little outside
// the back mesh's facets). A region is a few kilobytes whatever the part's size, and its cells
// follow a part of any shape more closely than its box.
constexpr double kShareMargin = 0.05;
constexpr int kShareCells = 16;

template <int D>
struct ShareRegion {
  static constexpr int kCells = D == 3 ? kShareCells * kShareCells * kShareCells : kShareCells * kShareCells;
  Box<D> box = Box<D>::empty();  // of the grid; empty: no region
  std::array<char, kCells> marked{};

  // Whether `other` meets a marked cell.
  bool meets(const Box<D>& other) const;
};

// The region of a part's mesh (empty for a mesh without elements).
template <int D>
ShareRegion<D> share_region(const Mesh<D>& mesh);

template <int D>
struct BackMeshShare {
  Mesh<D> mesh;                                     // back elements and their vertices: P1, no facets, no topology
  std::vector<Index> global_ids;                    // per vertex, its id in the whole back mesh (increasing)
  std::vector<std::vector<SymMat<D>>> log_metrics;  // per field, per vertex
};

// Collective. Rank 0 passes the whole `back` mesh, its elements' processes `part_of` and per field
// the log-metric at each back vertex; the others pass an empty mesh and nothing else. Returns this
// process's home share: the back elements of its part, in the back mesh's order. `bytes_sent`, when
// given, grows by what this process sent.
template <int D>
BackMeshShare<D> scatter_back_mesh(const Mesh<D>& back, std::span<const int> part_of,
                                   const std::vector<std::vector<SymMat<D>>>& log_metrics, long long* bytes_sent = nullptr);

// Collective: from every process's `home`, the back elements whose boxes meet `region` (none for an
// empty one), with their vertices and log-metrics; the elements in the order of their process and
// their place in its home, the vertices in the order of their global ids. `bytes_sent`, when given,
// grows by what this process sent.
template <int D>
BackMeshShare<D> share_around(const BackMeshShare<D>& home, const ShareRegion<D>& region, long long* bytes_sent = nullptr);

}  // namespace hocav
