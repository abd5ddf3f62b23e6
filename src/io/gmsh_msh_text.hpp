// The text of a gmsh .msh 4.1 ASCII file: the element types hocav reads and writes, and the pieces
// of a written file, shared by the serial writer (gmsh_msh.cpp) and the writer in runs
// (parallel/gmsh_msh_runs.hpp). Node orders: docs/formats.md, "Gmsh .msh 4.1".
#pragma once

#include <array>
#include <charconv>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "geom/vec.hpp"
#include "mesh/mesh.hpp"

namespace hocav::gmsh_msh {

struct ElementType {
  int gmsh_type;
  int dimension;
  int order;
  int node_count;
  std::string_view name;
  // The hocav local position of the node at each Gmsh position. Only tet10 differs from hocav's
  // order (Gmsh lists m23 before m13); a swap is its own inverse, so writing uses the same table.
  std::array<int, 10> hocav_position;
};

inline constexpr std::array<int, 10> kSameOrder{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
inline constexpr std::array<ElementType, 7> kElementTypes{{
    {15, 0, 1, 1, "point", kSameOrder},
    {1, 1, 1, 2, "line2", kSameOrder},
    {8, 1, 2, 3, "line3", kSameOrder},
    {2, 2, 1, 3, "tri3", kSameOrder},
    {9, 2, 2, 6, "tri6", kSameOrder},
    {4, 3, 1, 4, "tet4", kSameOrder},
    {11, 3, 2, 10, "tet10", {0, 1, 2, 3, 4, 5, 6, 7, 9, 8}},
}};

// The type of a Gmsh type number, or nullptr.
const ElementType* find_element_type(std::int64_t gmsh_type);
// The type of a simplex of `dimension` (0: a point) and `order`. Throws Error when there is none.
const ElementType& element_type(int dimension, int order);

// Buffered text output: numbers through std::to_chars (shortest form that reads back exactly).
class TextWriter {
 public:
  explicit TextWriter(std::ostream& out) : out_(out) { buffer_.reserve(kFlushSize + 256); }

  TextWriter& operator<<(std::string_view text) {
    buffer_ += text;
    return flush_if_full();
  }
  TextWriter& operator<<(char c) {
    buffer_ += c;
    return flush_if_full();
  }
  template <typename Number>
  requires std::is_arithmetic_v<Number> TextWriter& operator<<(Number value) {
    char digits[32];
    auto result = std::to_chars(digits, digits + sizeof digits, value);
    buffer_.append(digits, result.ptr);
    return flush_if_full();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kFlushSize = 1 << 16;
  TextWriter& flush_if_full() {
    if (buffer_.size() >= kFlushSize) flush();
    return *this;
  }
  std::ostream& out_;
  std::string buffer_;
};

inline constexpr std::string_view kMeshFormat = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";

// A point's three coordinates (z = 0 in 2D).
template <int D>
void write_point(TextWriter& out, const Vec<D>& point) {
  out << point[0] << ' ' << point[1] << ' ';
  if constexpr (D == 3)
    out << point[2];
  else
    out << '0';
}

// The $Entities section: entity i + 1 of dimension d has physical tag refs[d][i]; point entity i
// sits at points[i], and every curve, surface and volume gets the bounding box [low, high] of all
// nodes (a valid bound, and neither gmsh nor meshio uses it for a mesh).
template <int D>
void write_entities(TextWriter& out, const std::array<std::vector<int>, 4>& refs, const std::vector<Vec<D>>& points, const Vec<D>& low,
                    const Vec<D>& high) {
  out << "$Entities\n";
  for (int dimension = 0; dimension < 4; ++dimension) out << refs[dimension].size() << (dimension < 3 ? ' ' : '\n');
  for (int dimension = 0; dimension < 4; ++dimension)
    for (std::size_t entity = 0; entity < refs[dimension].size(); ++entity) {
      out << entity + 1 << ' ';
      if (dimension == 0) {
        write_point(out, points[entity]);
      } else {
        write_point(out, low);
        out << ' ';
        write_point(out, high);
      }
      out << " 1 " << refs[dimension][entity] << (dimension > 0 ? " 0\n" : "\n");
    }
  out << "$EndEntities\n";
}

// "$Nodes" and the head of its one block of `node_count` nodes tagged 1 to node_count, on the first
// entity of `dimension` (gmsh and meshio accept nodes classified on an entity of higher dimension
// than the elements that use them); an empty section whole.
void write_nodes_head(TextWriter& out, int dimension, Index node_count);

// "$Elements" and its head: `blocks` blocks of `elements` elements tagged 1 to `elements`.
void write_elements_head(TextWriter& out, std::size_t blocks, std::size_t elements);

// The head of a block of `count` elements of `type` on entity `entity` (from 1) of its dimension.
void write_block_head(TextWriter& out, std::size_t entity, const ElementType& type, std::size_t count);

// An element's line: its tag, then the numbers + 1 of its nodes in Gmsh's order (`numbers` in
// hocav's local order, from 0).
void write_element(TextWriter& out, std::size_t tag, const ElementType& type, const Index* numbers);

}  // namespace hocav::gmsh_msh
