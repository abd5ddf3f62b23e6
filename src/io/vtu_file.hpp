// VTK XML unstructured grids (.vtu) for ParaView: quadratic cells for P2 meshes, with point data
// (e.g. the metric as a tensor) and cell data (refs; later per-element quality).
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

struct VtuField {
  std::string name;
  int components = 1;          // 1 scalar, 3 vector, 9 tensor (ParaView's tensor layout)
  std::vector<double> values;  // one row of `components` per file node (point data) or element
};

struct VtuData {
  std::vector<VtuField> point_fields;  // rows in file node order: vertices, then P2 edge nodes
  std::vector<VtuField> cell_fields;   // rows in element order; "ref" is always written
};

template <int D>
void write_vtu(const std::string& path, const Mesh<D>& mesh, const VtuData& data = {});

// One DataArray of a .vtu: its XML attributes (all but the offset), and the bytes it appends.
struct VtuArray {
  std::string attributes;
  std::uint64_t bytes;
  std::function<void(std::ostream&)> write;
};

// The arrays of one mesh's .vtu as write_vtu writes them, for a file that several meshes fill one
// after another (write_vtu_runs): the mesh's points numbered from `first_point` on and its cells
// counted from `first_cell` on, every mesh P1 or every one P2. Holds `mesh` and `data`.
template <int D>
class VtuArrays {
 public:
  // Throws Error naming `path` for a field whose rows are not the mesh's points or cells.
  VtuArrays(const std::string& path, const Mesh<D>& mesh, const VtuData& data, std::int64_t first_point = 0, std::int64_t first_cell = 0);

  std::int64_t points() const { return points_; }
  std::int64_t cells() const { return cells_; }
  // The arrays in the order the appended block holds them.
  const std::vector<VtuArray>& in_block_order() const { return block_order_; }
  // The XML up to the appended block's first byte, for a file of `points` and `cells` in all whose
  // arrays append `bytes` each (in block order): each array's block then is its size as a UInt64,
  // then its bytes.
  void write_head(std::ostream& xml, std::int64_t points, std::int64_t cells, std::span<const std::uint64_t> bytes) const;
  // An array's size before its bytes.
  static void write_size(std::ostream& out, std::uint64_t size);
  // What follows the appended block.
  static constexpr std::string_view kTail = "\n  </AppendedData>\n</VTKFile>\n";

 private:
  std::int64_t points_, cells_;
  std::vector<VtuArray> block_order_;
  std::size_t point_data_, cell_data_, cells_arrays_;  // counts of each section's arrays (the points': one)
};

}  // namespace hocav
