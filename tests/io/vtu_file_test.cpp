// Reads back the layout of the .vtu files hocav writes (XML header, appended raw arrays). That
// VTK-based readers accept them is checked with meshio by tests/io/third_party_readers_test.py.
#include "io/vtu_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "base/error.hpp"
#include "cases/structured.hpp"
#include "temporary_files.hpp"

namespace hocav {
namespace {

using testing_support::temporary_path;

struct VtuArray {
  std::string type;
  int components = 1;
  std::string bytes;

  template <typename T>
  std::vector<T> values() const {
    std::vector<T> result(bytes.size() / sizeof(T));
    std::memcpy(result.data(), bytes.data(), result.size() * sizeof(T));
    return result;
  }
};

struct VtuContent {
  std::string header;
  std::map<std::string, VtuArray> arrays;
};

// The value of attribute `name` in an XML element's text, or "".
std::string attribute(const std::string& element, const std::string& name) {
  std::size_t at = element.find(" " + name + "=\"");
  if (at == std::string::npos) return "";
  at += name.size() + 3;
  return element.substr(at, element.find('"', at) - at);
}

VtuContent read_vtu(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::string opening = "<AppendedData encoding=\"raw\">\n_", closing = "\n  </AppendedData>\n</VTKFile>\n";
  const std::size_t data = text.find(opening) + opening.size();
  EXPECT_NE(text.find(opening), std::string::npos);
  EXPECT_TRUE(text.ends_with(closing));
  VtuContent content{text.substr(0, data), {}};
  std::size_t data_end = data;
  for (std::size_t at = content.header.find("<DataArray "); at != std::string::npos; at = content.header.find("<DataArray ", at + 1)) {
    std::string element = content.header.substr(at, content.header.find("/>", at) - at);
    EXPECT_EQ(attribute(element, "format"), "appended");
    std::string components = attribute(element, "NumberOfComponents");
    VtuArray array{attribute(element, "type"), components.empty() ? 1 : std::stoi(components), {}};
    std::size_t offset = data + std::stoull(attribute(element, "offset"));
    std::uint64_t size = 0;
    std::memcpy(&size, text.data() + offset, sizeof size);
    array.bytes = text.substr(offset + sizeof size, size);
    data_end = std::max<std::size_t>(data_end, offset + sizeof size + size);
    content.arrays[attribute(element, "Name")] = array;
  }
  // The arrays fill the appended block exactly.
  EXPECT_EQ(data_end, text.size() - closing.size());
  return content;
}

TEST(VtuFile, WritesCurvedTetrahedraWithFields) {
  Mesh<3> mesh = generate_cube(2);
  mesh.make_p2();
  for (Index e = 0; e < mesh.edge_count(); ++e) mesh.edge_node(e)[2] += 0.01 * std::sin(e);
  const Index node_count = mesh.vertex_count() + mesh.edge_count();
  VtuData data;
  data.point_fields.push_back({"metric", 9, std::vector<double>(static_cast<std::size_t>(node_count) * 9, 0.5)});
  data.point_fields.back().values[9 * (node_count - 1) + 8] = -3.25;
  data.cell_fields.push_back({"quality <&>", 1, std::vector<double>(static_cast<std::size_t>(mesh.element_count()), 1.0)});
  std::string path = temporary_path("cube_p2.vtu");
  write_vtu(path, mesh, data);

  VtuContent content = read_vtu(path);
  EXPECT_NE(content.header.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(content.header.find("NumberOfPoints=\"" + std::to_string(node_count) + "\" NumberOfCells=\"" +
                                std::to_string(mesh.element_count()) + "\""),
            std::string::npos);

  auto points = content.arrays.at("Points").values<double>();
  EXPECT_EQ(content.arrays.at("Points").components, 3);
  ASSERT_EQ(points.size(), static_cast<std::size_t>(node_count) * 3);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(points[3 * 5 + c], mesh.vertex(5)[c]);
    EXPECT_EQ(points[3 * (mesh.vertex_count() + 7) + c], mesh.edge_node(7)[c]);
  }
  auto connectivity = content.arrays.at("connectivity").values<std::int64_t>();
  auto offsets = content.arrays.at("offsets").values<std::int64_t>();
  auto types = content.arrays.at("types").values<std::uint8_t>();
  auto refs = content.arrays.at("ref").values<std::int32_t>();
  ASSERT_EQ(connectivity.size(), static_cast<std::size_t>(mesh.element_count()) * 10);
  ASSERT_EQ(offsets.size(), static_cast<std::size_t>(mesh.element_count()));
  for (Index k = 0; k < mesh.element_count(); ++k) {
    for (int i = 0; i < 4; ++i) EXPECT_EQ(connectivity[10 * k + i], mesh.element(k)[i]);
    for (int e = 0; e < 6; ++e) EXPECT_EQ(connectivity[10 * k + 4 + e], mesh.vertex_count() + mesh.element_edge(k, e));
    EXPECT_EQ(offsets[k], 10 * (k + 1));
    EXPECT_EQ(types[k], 24);  // VTK_QUADRATIC_TETRA
    EXPECT_EQ(refs[k], mesh.element_ref(k));
  }
  EXPECT_EQ(content.arrays.at("metric").components, 9);
  EXPECT_EQ(content.arrays.at("metric").values<double>().back(), -3.25);
  EXPECT_EQ(content.arrays.at("quality &lt;&amp;&gt;").values<double>().size(), static_cast<std::size_t>(mesh.element_count()));
}

TEST(VtuFile, WritesStraightTrianglesInThePlane) {
  Mesh<2> mesh = generate_square(3);
  std::string path = temporary_path("square_p1.vtu");
  write_vtu(path, mesh);
  VtuContent content = read_vtu(path);
  auto points = content.arrays.at("Points").values<double>();
  ASSERT_EQ(points.size(), static_cast<std::size_t>(mesh.vertex_count()) * 3);
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    EXPECT_EQ(points[3 * v], mesh.vertex(v)[0]);
    EXPECT_EQ(points[3 * v + 1], mesh.vertex(v)[1]);
    EXPECT_EQ(points[3 * v + 2], 0.0);
  }
  auto types = content.arrays.at("types").values<std::uint8_t>();
  ASSERT_EQ(types.size(), static_cast<std::size_t>(mesh.element_count()));
  EXPECT_EQ(types[0], 5);  // VTK_TRIANGLE
  EXPECT_EQ(content.arrays.at("offsets").values<std::int64_t>().back(), 3 * mesh.element_count());
}

TEST(VtuFile, WritesQuadraticTriangles) {
  Mesh<2> mesh = generate_square(2);
  mesh.make_p2();
  VtuContent content = read_vtu((write_vtu(temporary_path("square_p2.vtu"), mesh), temporary_path("square_p2.vtu")));
  EXPECT_EQ(content.arrays.at("types").values<std::uint8_t>()[0], 22);  // VTK_QUADRATIC_TRIANGLE
  EXPECT_EQ(content.arrays.at("connectivity").values<std::int64_t>()[3], mesh.vertex_count() + mesh.element_edge(0, 0));
}

TEST(VtuFile, RefusesFieldsOfTheWrongSize) {
  Mesh<2> mesh = generate_square(2);
  std::string path = temporary_path("bad_field.vtu");
  VtuData data;
  data.point_fields.push_back({"size", 1, std::vector<double>(3, 1.0)});
  try {
    write_vtu(path, mesh, data);
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(path + ": point field 'size' has 3 values, expected 9 rows of 1"), std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(std::ifstream(path).good());
  data.point_fields.clear();
  data.cell_fields.push_back({"ref", 1, std::vector<double>(static_cast<std::size_t>(mesh.element_count()), 1.0)});
  EXPECT_THROW(write_vtu(path, mesh, data), Error);
}

}  // namespace
}  // namespace hocav
