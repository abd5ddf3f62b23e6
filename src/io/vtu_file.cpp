// VTK XML unstructured grid with the data appended as raw binary (header_type UInt64): compact and
// fast for million-element meshes, read by VTK/ParaView and meshio. Cell types and node orders:
// docs/formats.md, "VTK .vtu" (VTK's quadratic order is hocav's).
#include "io/vtu_file.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string_view>
#include <type_traits>

#include "base/error.hpp"
#include "io/atomic_output.hpp"
#include "io/xml_escape.hpp"

namespace hocav {
namespace {

// VTK cell types: linear and quadratic triangle and tetrahedron.
constexpr std::uint8_t kVtkCellType[2][2] = {{5, 22}, {10, 24}};

class BinaryWriter {
 public:
  explicit BinaryWriter(std::ostream& out) : out_(out) { buffer_.reserve(kFlushSize + 64); }

  template <typename T>
  requires std::is_arithmetic_v<T>
  void put(T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    buffer_.append(bytes, sizeof(T));
    if (buffer_.size() >= kFlushSize) flush();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kFlushSize = 1 << 20;
  std::ostream& out_;
  std::string buffer_;
};

// NumberOfComponents is left out for scalars (VTK's default), so meshio reads them as 1-D arrays.
std::string attributes(std::string_view type, std::string_view name, int components) {
  std::string text = "type=\"" + std::string(type) + "\" Name=\"" + xml_escaped(name) + "\"";
  if (components != 1) text += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  return text;
}

// An array of `count` values that `put_values` puts, each of type T.
template <typename T, typename PutValues>
VtuArray array_of(std::string attributes, std::size_t count, PutValues put_values) {
  return {std::move(attributes), count * sizeof(T), [put_values](std::ostream& out) {
            BinaryWriter writer(out);
            put_values(writer);
            writer.flush();
          }};
}

// The arrays of user fields, checked against the number of rows (points or cells) they describe.
std::vector<VtuArray> field_arrays(const std::vector<VtuField>& fields, std::size_t rows, std::string_view kind, const std::string& path) {
  std::vector<VtuArray> arrays;
  for (const VtuField& field : fields) {
    if (field.components < 1 || field.values.size() != rows * static_cast<std::size_t>(field.components))
      throw Error(path + ": " + std::string(kind) + " field '" + field.name + "' has " + std::to_string(field.values.size()) +
                  " values, expected " + std::to_string(rows) + " rows of " + std::to_string(field.components));
    if (kind == "cell" && field.name == "ref") throw Error(path + ": cell field name 'ref' is reserved for the element refs");
    arrays.push_back(
        array_of<double>(attributes("Float64", field.name, field.components), field.values.size(), [&field](BinaryWriter& out) {
          for (double value : field.values) out.put(value);
        }));
  }
  return arrays;
}

// The refs of the mesh's elements.
template <int D>
VtuArray refs_array(const Mesh<D>& mesh) {
  return array_of<std::int32_t>(attributes("Int32", "ref", 1), static_cast<std::size_t>(mesh.element_count()), [&mesh](BinaryWriter& out) {
    for (Index k = 0; k < mesh.element_count(); ++k) out.put(std::int32_t{mesh.element_ref(k)});
  });
}

// The mesh's points: its vertices, then its P2 nodes.
template <int D>
VtuArray points_array(const Mesh<D>& mesh, std::size_t count) {
  return array_of<double>(attributes("Float64", "Points", 3), count * 3, [&mesh](BinaryWriter& out) {
    auto put_point = [&out](const Vec<D>& point) {
      for (int c = 0; c < 3; ++c) out.put(c < D ? point[c] : 0.0);
    };
    for (const auto& vertex : mesh.vertices()) put_point(vertex);
    for (Index e = 0; mesh.is_p2() && e < mesh.edge_count(); ++e) put_point(mesh.edge_node(e));
  });
}

// The Cells arrays: each element's points (numbered from `first_point`), the offsets of their ends
// (the file's cells before counted from `first_cell`), the cell types.
template <int D>
std::vector<VtuArray> cells_arrays(const Mesh<D>& mesh, std::int64_t first_point, std::int64_t first_cell) {
  const bool p2 = mesh.is_p2();
  const auto elements = static_cast<std::int64_t>(mesh.element_count());
  const std::int64_t size = D + 1 + (p2 ? Simplex<D>::kEdges : 0);
  const std::int64_t first_node = first_point + mesh.vertex_count();
  std::vector<VtuArray> arrays;
  arrays.push_back(array_of<std::int64_t>(attributes("Int64", "connectivity", 1), static_cast<std::size_t>(elements * size),
                                          [&mesh, p2, first_point, first_node](BinaryWriter& out) {
                                            for (Index k = 0; k < mesh.element_count(); ++k) {
                                              for (Index v : mesh.element(k)) out.put(first_point + v);
                                              for (int e = 0; p2 && e < Simplex<D>::kEdges; ++e)
                                                out.put(first_node + mesh.element_edge(k, e));
                                            }
                                          }));
  arrays.push_back(array_of<std::int64_t>(attributes("Int64", "offsets", 1), static_cast<std::size_t>(elements),
                                          [first_cell, elements, size](BinaryWriter& out) {
                                            for (std::int64_t k = 1; k <= elements; ++k) out.put((first_cell + k) * size);
                                          }));
  arrays.push_back(
      array_of<std::uint8_t>(attributes("UInt8", "types", 1), static_cast<std::size_t>(elements), [elements, p2](BinaryWriter& out) {
        for (std::int64_t k = 0; k < elements; ++k) out.put(kVtkCellType[D - 2][p2 ? 1 : 0]);
      }));
  return arrays;
}

}  // namespace

// The appended block holds the arrays in the reverse of their order in the XML. meshio 5.0 turns
// raw data into base64 by rewriting each DataArray's offset in data order, finding it by its
// current offset; in XML order a rewritten offset could equal a later array's raw offset and be
// taken for it.
template <int D>
VtuArrays<D>::VtuArrays(const std::string& path, const Mesh<D>& mesh, const VtuData& data, std::int64_t first_point,
                        std::int64_t first_cell)
    : points_(mesh.vertex_count() + (mesh.is_p2() ? mesh.edge_count() : 0)), cells_(mesh.element_count()) {
  std::vector<VtuArray> xml_order = field_arrays(data.point_fields, static_cast<std::size_t>(points_), "point", path);
  point_data_ = xml_order.size();
  xml_order.push_back(refs_array(mesh));
  for (VtuArray& array : field_arrays(data.cell_fields, static_cast<std::size_t>(cells_), "cell", path))
    xml_order.push_back(std::move(array));
  cell_data_ = xml_order.size() - point_data_;
  xml_order.push_back(points_array(mesh, static_cast<std::size_t>(points_)));
  std::vector<VtuArray> cells = cells_arrays(mesh, first_point, first_cell);
  cells_arrays_ = cells.size();
  for (VtuArray& array : cells) xml_order.push_back(std::move(array));
  block_order_.assign(std::make_move_iterator(xml_order.rbegin()), std::make_move_iterator(xml_order.rend()));
}

template <int D>
void VtuArrays<D>::write_head(std::ostream& xml, std::int64_t points, std::int64_t cells, std::span<const std::uint64_t> bytes) const {
  std::vector<std::uint64_t> offsets;  // in block order
  std::uint64_t offset = 0;
  for (std::uint64_t size : bytes) {
    offsets.push_back(offset);
    offset += sizeof(std::uint64_t) + size;
  }
  std::size_t next = 0;  // in XML order
  const auto write_section = [&](std::size_t count) {
    for (std::size_t end = next + count; next < end; ++next) {
      const std::size_t block = block_order_.size() - 1 - next;
      xml << "        <DataArray " << block_order_[block].attributes << " format=\"appended\" offset=\"" << offsets[block] << "\"/>\n";
    }
  };
  xml << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
      << (std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n"
      << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << points << "\" NumberOfCells=\"" << cells << "\">\n"
      << "      <PointData>\n";
  write_section(point_data_);
  xml << "      </PointData>\n      <CellData Scalars=\"ref\">\n";
  write_section(cell_data_);
  xml << "      </CellData>\n      <Points>\n";
  write_section(1);
  xml << "      </Points>\n      <Cells>\n";
  write_section(cells_arrays_);
  xml << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n_";
}

template <int D>
void VtuArrays<D>::write_size(std::ostream& out, std::uint64_t size) {
  char bytes[sizeof size];
  std::memcpy(bytes, &size, sizeof size);
  out.write(bytes, sizeof size);
}

template <int D>
void write_vtu(const std::string& path, const Mesh<D>& mesh, const VtuData& data) {
  const VtuArrays<D> arrays(path, mesh, data);
  std::vector<std::uint64_t> bytes;
  for (const VtuArray& array : arrays.in_block_order()) bytes.push_back(array.bytes);
  AtomicOutput output(path);
  std::ostream& xml = output.stream();
  arrays.write_head(xml, arrays.points(), arrays.cells(), bytes);
  for (const VtuArray& array : arrays.in_block_order()) {
    VtuArrays<D>::write_size(xml, array.bytes);
    array.write(xml);
  }
  // meshio finds the end of the raw data at the last newline before </AppendedData>.
  xml << VtuArrays<D>::kTail;
  output.commit();
}

template class VtuArrays<2>;
template class VtuArrays<3>;
template void write_vtu(const std::string&, const Mesh<2>&, const VtuData&);
template void write_vtu(const std::string&, const Mesh<3>&, const VtuData&);

}  // namespace hocav
