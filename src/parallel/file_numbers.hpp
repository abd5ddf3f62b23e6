// The numbers a mesh file written in runs gives the entities of a distributed mesh (docs/distributed.md
// §Writing in runs), whatever the file's format: each vertex and P2 node once, however many parts hold
// it, and each feature line once. Shared by the Gamma and gmsh writers in runs.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "mesh/simplex.hpp"
#include "parallel/face_key.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// The tags an entity carries in the file.
constexpr char kCornerFlag = 1, kRequiredFlag = 2, kRidgeFlag = 4;

// A vertex on its way to the process of its run of global ids, which writes it.
template <int D>
struct VertexToRun {
  Index id;
  Vec<D> point;
  int ref;
  char flags;  // kCornerFlag, kRequiredFlag
};

// An element, facet or line on its way to the process that writes it.
template <std::size_t M>
struct PlacedRow {
  Index place;  // its place among the file's entities of its kind, when they have an order
  int ref;
  char flags;                    // a facet's or line's kRidgeFlag, kRequiredFlag
  std::array<Index, M> numbers;  // its vertices' file numbers, then its nodes' (P2; kNoIndex for P1)
};

// A line's row: its ends' file numbers in its order, then its P2 node's.
using LineRow = PlacedRow<3>;

// Every process at once: the file numbers (from 0) of the part's vertices and P2 nodes. The
// vertices go to the processes of their runs of global ids, which number them in id order, run
// after run, and keep one row of each (its point, ref and tags) to write; a P2 file's nodes come
// after every vertex, those of each process's own edges in its edge table's order, then the edges
// several parts may hold (both ends on an interface), each numbered once by the process its ends
// hash to, rank after rank. One process holding a whole mesh (the others empty) numbers the
// vertices by their global ids and the nodes in its edge table's order. Throws Error (naming `path`)
// when two parts give a vertex different points or an edge different nodes.
template <int D>
class FileNumbers {
 public:
  FileNumbers(const std::string& path, const MeshPart<D>& part);

  Index vertex_count() const { return vertex_count_; }  // over the file
  Index node_count() const { return node_count_; }      // beyond the vertices, over the file
  bool p2() const { return p2_; }                       // whether any part is P2

  Index first_vertex() const { return first_vertex_; }
  // The vertices this process writes, in file order from first_vertex() on.
  const std::vector<VertexToRun<D>>& vertex_rows() const { return vertex_rows_; }
  // The P2 nodes this process writes, in file order, and the file number of the first.
  const std::vector<Vec<D>>& written_nodes() const { return written_nodes_; }
  Index first_node() const { return first_node_; }

  // A simplex's file numbers: its vertices', then its edges' nodes' (P2, in the local edge order of
  // a simplex of its dimension; kNoIndex for P1).
  template <std::size_t N>
  std::array<Index, N + N*(N - 1) / 2> simplex(const std::array<Index, N>& vertices) const {
    std::array<Index, N + N*(N - 1) / 2> numbers;
    numbers.fill(kNoIndex);
    for (std::size_t i = 0; i < N; ++i) numbers[i] = number_[vertices[i]];
    if (part_.mesh.is_p2())
      for (std::size_t e = 0; e < N * (N - 1) / 2; ++e) {
        std::array<int, 2> ends{0, 1};
        if constexpr (N > 2) ends = edge_vertices<static_cast<int>(N) - 1>(static_cast<int>(e));
        numbers[N + e] = node_number_[part_.mesh.find_edge(vertices[ends[0]], vertices[ends[1]])];
      }
    return numbers;
  }

  // Every process at once, 3D: the feature lines this process writes, each line of the distributed
  // mesh on one process: its part's own lines (an end off the interfaces), in order, then of those
  // several parts may hold the first part's (in rank order), kept by the process their ends hash to.
  // Each row's place is line_order's for the line (kNoIndex when line_order is empty).
  std::vector<LineRow> lines_once(std::span<const Index> line_order) const;

 private:
  void number_vertices();
  void number_nodes();
  bool shared_edge(Index a, Index b) const { return shared_[a] && shared_[b]; }
  FaceKey<2> edge_key(Index a, Index b) const { return sorted_key<2>({part_.global_ids[a], part_.global_ids[b]}); }

  const std::string& path_;
  const MeshPart<D>& part_;
  bool p2_ = false;
  Index vertex_count_ = 0, node_count_ = 0, first_vertex_ = 0, first_node_ = 0;
  std::vector<Index> number_;                // per part vertex, its file number
  std::vector<char> shared_;                 // per part vertex, whether another part holds it
  std::vector<Index> node_number_;           // per part edge (P2), its node's file number
  std::vector<VertexToRun<D>> vertex_rows_;  // the vertices this process writes, in order
  std::vector<Vec<D>> written_nodes_;        // the nodes this process writes, in order
};

}  // namespace hocav
