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

// One DataArray: its XML attributes (all but the offset), and its bytes in the appended block.
struct AppendedArray {
  std::string attributes;
  std::uint64_t bytes;
  std::function<void(BinaryWriter&)> write;
  std::uint64_t offset = 0;
};

// NumberOfComponents is left out for scalars (VTK's default), so meshio reads them as 1-D arrays.
std::string attributes(std::string_view type, std::string_view name, int components) {
  std::string text = "type=\"" + std::string(type) + "\" Name=\"" + xml_escaped(name) + "\"";
  if (components != 1) text += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  return text;
}

// The arrays of user fields, checked against the number of rows (points or cells) they describe.
std::vector<AppendedArray> field_arrays(const std::vector<VtuField>& fields, std::size_t rows, std::string_view kind,
                                        const std::string& path) {
  std::vector<AppendedArray> arrays;
  for (const VtuField& field : fields) {
    if (field.components < 1 || field.values.size() != rows * static_cast<std::size_t>(field.components))
      throw Error(path + ": " + std::string(kind) + " field '" + field.name + "' has " + std::to_string(field.values.size()) +
                  " values, expected " + std::to_string(rows) + " rows of " + std::to_string(field.components));
    if (kind == "cell" && field.name == "ref") throw Error(path + ": cell field name 'ref' is reserved for the element refs");
    arrays.push_back(
        {attributes("Float64", field.name, field.components), field.values.size() * sizeof(double), [&field](BinaryWriter& out) {
           for (double value : field.values) out.put(value);
         }});
  }
  return arrays;
}

void write_array_elements(std::ostream& xml, const std::vector<AppendedArray>& arrays) {
  for (const AppendedArray& array : arrays)
    xml << "        <DataArray " << array.attributes << " format=\"appended\" offset=\"" << array.offset << "\"/>\n";
}

}  // namespace

template <int D>
void write_vtu(const std::string& path, const Mesh<D>& mesh, const VtuData& data) {
  const bool p2 = mesh.is_p2();
  const auto vertex_count = static_cast<std::size_t>(mesh.vertex_count());
  const std::size_t node_count = vertex_count + (p2 ? static_cast<std::size_t>(mesh.edge_count()) : 0);
  const auto element_count = static_cast<std::size_t>(mesh.element_count());
  const std::size_t element_size = D + 1 + (p2 ? Simplex<D>::kEdges : 0);

  std::vector<AppendedArray> point_data = field_arrays(data.point_fields, node_count, "point", path);
  std::vector<AppendedArray> cell_data{{attributes("Int32", "ref", 1), element_count * sizeof(std::int32_t), [&mesh](BinaryWriter& out) {
                                          for (Index k = 0; k < mesh.element_count(); ++k) out.put(std::int32_t{mesh.element_ref(k)});
                                        }}};
  for (AppendedArray& array : field_arrays(data.cell_fields, element_count, "cell", path)) cell_data.push_back(std::move(array));
  std::vector<AppendedArray> points{{attributes("Float64", "Points", 3), node_count * 3 * sizeof(double), [&mesh, p2](BinaryWriter& out) {
                                       auto put_point = [&out](const Vec<D>& point) {
                                         for (int c = 0; c < 3; ++c) out.put(c < D ? point[c] : 0.0);
                                       };
                                       for (const auto& vertex : mesh.vertices()) put_point(vertex);
                                       for (Index e = 0; p2 && e < mesh.edge_count(); ++e) put_point(mesh.edge_node(e));
                                     }}};
  std::vector<AppendedArray> cells{
      {attributes("Int64", "connectivity", 1), element_count * element_size * sizeof(std::int64_t),
       [&mesh, p2](BinaryWriter& out) {
         for (Index k = 0; k < mesh.element_count(); ++k) {
           for (Index v : mesh.element(k)) out.put(std::int64_t{v});
           for (int e = 0; p2 && e < Simplex<D>::kEdges; ++e) out.put(std::int64_t{mesh.vertex_count()} + mesh.element_edge(k, e));
         }
       }},
      {attributes("Int64", "offsets", 1), element_count * sizeof(std::int64_t),
       [element_count, element_size](BinaryWriter& out) {
         for (std::size_t k = 1; k <= element_count; ++k) out.put(static_cast<std::int64_t>(k * element_size));
       }},
      {attributes("UInt8", "types", 1), element_count * sizeof(std::uint8_t), [element_count, p2](BinaryWriter& out) {
         for (std::size_t k = 0; k < element_count; ++k) out.put(kVtkCellType[D - 2][p2 ? 1 : 0]);
       }}};

  // The appended block holds the arrays in the reverse of their order in the XML. meshio 5.0 turns
  // raw data into base64 by rewriting each DataArray's offset in data order, finding it by its
  // current offset; in XML order a rewritten offset could equal a later array's raw offset and
  // be taken for it.
  std::vector<AppendedArray>* sections[] = {&point_data, &cell_data, &points, &cells};
  std::vector<AppendedArray*> data_order;
  for (auto section = std::rbegin(sections); section != std::rend(sections); ++section)
    for (auto array = (*section)->rbegin(); array != (*section)->rend(); ++array) data_order.push_back(&*array);
  std::uint64_t offset = 0;
  for (AppendedArray* array : data_order) {
    array->offset = offset;
    offset += sizeof(std::uint64_t) + array->bytes;
  }

  AtomicOutput output(path);
  std::ostream& xml = output.stream();
  xml << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
      << (std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n"
      << "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"" << node_count << "\" NumberOfCells=\"" << element_count << "\">\n"
      << "      <PointData>\n";
  write_array_elements(xml, point_data);
  xml << "      </PointData>\n      <CellData Scalars=\"ref\">\n";
  write_array_elements(xml, cell_data);
  xml << "      </CellData>\n      <Points>\n";
  write_array_elements(xml, points);
  xml << "      </Points>\n      <Cells>\n";
  write_array_elements(xml, cells);
  xml << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n_";
  BinaryWriter out(xml);
  for (const AppendedArray* array : data_order) {
    out.put(array->bytes);
    array->write(out);
  }
  out.flush();
  // meshio finds the end of the raw data at the last newline before </AppendedData>.
  xml << "\n  </AppendedData>\n</VTKFile>\n";
  output.commit();
}

template void write_vtu(const std::string&, const Mesh<2>&, const VtuData&);
template void write_vtu(const std::string&, const Mesh<3>&, const VtuData&);

}  // namespace hocav
