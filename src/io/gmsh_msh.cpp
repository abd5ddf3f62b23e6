// Gmsh MSH 4.1 ASCII: reading into RawMesh (then the shared assembly) and writing with one entity
// per ref, so that gmsh and meshio see refs as physical tags. Node orders: docs/formats.md, "Gmsh .msh 4.1".
#include "io/gmsh_msh.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cstdint>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <string_view>
#include <type_traits>

#include "base/error.hpp"
#include "base/index_hash_map.hpp"
#include "io/atomic_output.hpp"
#include "io/gmsh_msh_text.hpp"
#include "io/mesh_assembly.hpp"
#include "io/printable_excerpt.hpp"
#include "io/text_scanner.hpp"

namespace hocav {
namespace {

constexpr std::string_view kConvertHint = "convert with: gmsh IN.msh -0 -format msh41 -save_all -o OUT.msh";
constexpr std::string_view kSupportedTypes = "15 point, 1 line2, 8 line3, 2 tri3, 9 tri6, 4 tet4, 11 tet10";

using gmsh_msh::element_type;
using gmsh_msh::ElementType;
using gmsh_msh::find_element_type;
using gmsh_msh::TextWriter;

// Shape names of the Gmsh element types hocav refuses, so the message says what was found.
std::string_view unsupported_type_name(std::int64_t gmsh_type) {
  switch (gmsh_type) {
    case 3:
    case 10:
    case 16: return "quadrangle";
    case 5:
    case 12:
    case 17:
    case 92:
    case 93: return "hexahedron";
    case 6:
    case 13:
    case 18:
    case 90:
    case 91: return "prism";
    case 7:
    case 14:
    case 19:
    case 118:
    case 119: return "pyramid";
    case 20:
    case 21:
    case 22:
    case 23:
    case 24:
    case 25: return "triangle of order 3 or more";
    case 26:
    case 27:
    case 28: return "line of order 3 or more";
    case 29:
    case 30:
    case 31: return "tetrahedron of order 3 or more";
    default: return "unknown";
  }
}

// Everything hocav keeps from a .msh file: nodes in file order, and per dimension one list of
// elements of a single type, with node file ids in hocav's local order and their refs.
struct MshElementBlock {
  const ElementType* type = nullptr;
  std::vector<Index> nodes;
  std::vector<int> refs;
};

struct MshContent {
  std::vector<Vec3> nodes;
  std::array<MshElementBlock, 4> lists;  // by dimension: points, lines, triangles, tetrahedra
  std::size_t first_nonzero_z_line = 0;
  double first_nonzero_z = 0;
};

// Reserving from a count read in the file: never more than this before the data proves it.
constexpr std::int64_t kMaxUncheckedReserve = 1 << 20;

// Makes room for `count` more entries, growing geometrically so that many small blocks stay linear.
template <typename T>
void bounded_reserve(std::vector<T>& vector, std::int64_t count) {
  std::size_t needed = vector.size() + static_cast<std::size_t>(std::min(count, kMaxUncheckedReserve));
  if (needed > vector.capacity()) vector.reserve(std::max(needed, 2 * vector.capacity()));
}

class MshReader {
 public:
  explicit MshReader(const std::string& path) : in_(path) {}

  MshContent read() {
    if (in_.next_token() != "$MeshFormat") in_.fail("$MeshFormat", "not a Gmsh .msh file (it must start with $MeshFormat)");
    read_format();
    bool have_nodes = false, have_elements = false;
    for (std::string_view token = in_.next_token(); !token.empty(); token = in_.next_token()) {
      std::string section(token);
      if (section == "$Entities") {
        if (have_elements) in_.fail(section, "comes after $Elements");
        read_entities();
      } else if (section == "$Nodes") {
        if (have_nodes) in_.fail(section, "a second $Nodes section");
        read_nodes();
        have_nodes = true;
      } else if (section == "$Elements") {
        if (!have_nodes) in_.fail(section, "comes before $Nodes");
        if (have_elements) in_.fail(section, "a second $Elements section");
        read_elements();
        have_elements = true;
      } else if (section == "$PhysicalNames") {
        skip_section(section);  // names are not kept; the physical tags themselves are in $Entities
      } else if (section.size() > 1 && section[0] == '$' && section.compare(0, 4, "$End") != 0) {
        std::cerr << in_.path() << ": warning: skipping section " << printable_excerpt(section) << " (not used by hocav), line "
                  << in_.line() << "\n";
        skip_section(section);
      } else {
        throw Error(in_.path() + ": expected a section such as $Nodes, found '" + printable_excerpt(token) + "', line " +
                    std::to_string(in_.line()));
      }
    }
    if (!have_nodes) throw Error(in_.path() + ": no $Nodes section");
    if (!have_elements) throw Error(in_.path() + ": no $Elements section");
    return std::move(content_);
  }

 private:
  void expect(std::string_view expected, std::string_view section) {
    std::string_view token = in_.next_token();
    if (token.empty()) in_.fail(section, "unexpected end of file, expected " + std::string(expected));
    if (token != expected) in_.fail(section, "expected " + std::string(expected) + ", found '" + printable_excerpt(token) + "'");
  }

  void skip_section(const std::string& section) {
    std::string end = "$End" + section.substr(1);
    for (std::string_view token = in_.next_token(); token != end; token = in_.next_token())
      if (token.empty()) in_.fail(section, "no " + end + " (truncated file?)");
  }

  std::int64_t read_count(std::string_view section) {
    std::int64_t count = in_.next_integer(section);
    if (count < 0) in_.fail(section, "negative count " + std::to_string(count));
    return count;
  }

  int read_int(std::string_view section) {
    std::int64_t value = in_.next_integer(section);
    if (value < INT_MIN || value > INT_MAX) in_.fail(section, "integer out of range " + std::to_string(value));
    return static_cast<int>(value);
  }

  void read_format() {
    const std::string_view section = "$MeshFormat";
    std::string version(in_.next_token());
    if (version != "4.1")
      in_.fail(section, "version '" + printable_excerpt(version, 20) + "' is not supported: hocav reads MSH 4.1 ASCII; " +
                            std::string(kConvertHint));
    std::int64_t file_type = in_.next_integer(section);
    if (file_type == 1)
      in_.fail(section, "binary .msh is not supported: hocav reads MSH 4.1 ASCII; " + std::string(kConvertHint) + " (without -bin)");
    if (file_type != 0) in_.fail(section, "file type " + std::to_string(file_type) + " is neither 0 (ASCII) nor 1 (binary)");
    in_.next_integer(section);  // data size: meaningful for binary files only
    expect("$EndMeshFormat", section);
  }

  // Entity (dimension, tag) -> its first physical tag, which becomes the ref of its elements.
  void read_entities() {
    const std::string_view section = "$Entities";
    std::array<std::int64_t, 4> counts{};
    for (auto& count : counts) count = read_count(section);
    for (int dimension = 0; dimension < 4; ++dimension)
      for (std::int64_t i = 0; i < counts[dimension]; ++i) {
        int tag = read_int(section);
        for (int r = 0; r < (dimension == 0 ? 3 : 6); ++r) in_.next_real(section);  // position or bounding box
        std::int64_t physical_count = read_count(section);
        for (std::int64_t p = 0; p < physical_count; ++p) {
          int physical = read_int(section);
          if (p == 0) physical_tags_[{dimension, tag}] = physical;
        }
        if (dimension > 0)
          for (std::int64_t b = read_count(section); b > 0; --b) in_.next_integer(section);  // bounding entities
      }
    expect("$EndEntities", section);
  }

  void read_nodes() {
    const std::string_view section = "$Nodes";
    std::int64_t block_count = read_count(section), node_count = read_count(section);
    in_.next_integer(section);  // min and max node tags: the tags themselves are checked
    in_.next_integer(section);
    bounded_reserve(content_.nodes, node_count);
    node_ids_.reserve(static_cast<std::size_t>(std::min(node_count, kMaxUncheckedReserve)));
    for (std::int64_t block = 0; block < block_count; ++block) {
      int entity_dimension = read_int(section);
      if (entity_dimension < 0 || entity_dimension > 3) in_.fail(section, "entity dimension " + std::to_string(entity_dimension));
      read_int(section);  // entity tag: nodes are not classified in hocav
      int parametric = read_int(section);
      if (parametric != 0 && parametric != 1) in_.fail(section, "parametric flag must be 0 or 1");
      std::int64_t count = read_count(section);
      std::size_t first = content_.nodes.size();
      for (std::int64_t i = 0; i < count; ++i) {
        std::int64_t tag = in_.next_integer(section);
        if (tag < 1) in_.fail(section, "node tag " + std::to_string(tag) + " is not positive");
        Index id = checked_index(first + static_cast<std::size_t>(i), "nodes");
        if (node_ids_.insert(static_cast<std::uint64_t>(tag), id) != id)
          in_.fail(section, "node tag " + std::to_string(tag) + " is defined twice");
      }
      for (std::int64_t i = 0; i < count; ++i) {
        Vec3 point;
        for (int c = 0; c < 3; ++c) point[c] = in_.next_real(section);
        if (point[2] != 0 && content_.first_nonzero_z_line == 0) {
          content_.first_nonzero_z_line = in_.line();
          content_.first_nonzero_z = point[2];
        }
        for (int u = 0; u < parametric * entity_dimension; ++u) in_.next_real(section);
        content_.nodes.push_back(point);
      }
    }
    if (static_cast<std::int64_t>(content_.nodes.size()) != node_count)
      in_.fail(section,
               "the header announces " + std::to_string(node_count) + " nodes, the blocks hold " + std::to_string(content_.nodes.size()));
    expect("$EndNodes", section);
  }

  void read_elements() {
    const std::string_view section = "$Elements";
    std::int64_t block_count = read_count(section), element_count = read_count(section), read_so_far = 0;
    in_.next_integer(section);  // min and max element tags: hocav renumbers elements
    in_.next_integer(section);
    for (std::int64_t block = 0; block < block_count; ++block) {
      int entity_dimension = read_int(section), entity_tag = read_int(section);
      std::int64_t gmsh_type = in_.next_integer(section);
      const ElementType* type = find_element_type(gmsh_type);
      if (type == nullptr)
        in_.fail(section, "element type " + std::to_string(gmsh_type) + " (" + std::string(unsupported_type_name(gmsh_type)) +
                              ") is not supported; hocav reads " + std::string(kSupportedTypes));
      if (type->dimension != entity_dimension)
        in_.fail(section, std::string(type->name) + " elements in a block of dimension " + std::to_string(entity_dimension));
      MshElementBlock& list = content_.lists[type->dimension];
      if (list.type != nullptr && list.type != type)
        in_.fail(section, "mixes " + std::string(list.type->name) + " and " + std::string(type->name) +
                              " elements (P1 and P2 elements of one dimension cannot be mixed)");
      list.type = type;
      int ref = entity_tag;
      if (auto physical = physical_tags_.find({entity_dimension, entity_tag}); physical != physical_tags_.end()) ref = physical->second;
      std::int64_t count = read_count(section);
      bounded_reserve(list.nodes, std::min(count, kMaxUncheckedReserve) * type->node_count);
      bounded_reserve(list.refs, count);
      for (std::int64_t i = 0; i < count; ++i) {
        in_.next_integer(section);  // element tag
        std::size_t first = list.nodes.size();
        list.nodes.resize(first + static_cast<std::size_t>(type->node_count));
        for (int position = 0; position < type->node_count; ++position)
          list.nodes[first + static_cast<std::size_t>(type->hocav_position[position])] = node_id(section);
        list.refs.push_back(ref);
      }
      read_so_far += count;
    }
    if (read_so_far != element_count)
      in_.fail(section,
               "the header announces " + std::to_string(element_count) + " elements, the blocks hold " + std::to_string(read_so_far));
    expect("$EndElements", section);
  }

  Index node_id(std::string_view section) {
    std::int64_t tag = in_.next_integer(section);
    Index id = tag < 1 ? kNoIndex : node_ids_.find(static_cast<std::uint64_t>(tag));
    if (id == kNoIndex) in_.fail(section, "node tag " + std::to_string(tag) + " is not defined");
    return id;
  }

  TextScanner in_;
  MshContent content_;
  IndexHashMap node_ids_;  // node tag -> position in the file
  std::map<std::pair<int, int>, int> physical_tags_;
};

// 3 when there are tetrahedra; 2 for triangles in the plane z = 0; anything else is refused.
int mesh_dimension(const MshContent& content, const std::string& path) {
  if (content.lists[3].type != nullptr) return 3;
  if (content.lists[2].type == nullptr) throw Error(path + ": $Elements: no triangles or tetrahedra");
  if (content.first_nonzero_z_line != 0) {
    std::ostringstream z;
    z << content.first_nonzero_z;
    throw Error(path + ": $Nodes: triangles with z = " + z.str() +
                " make a surface mesh, which hocav does not support (it reads planar triangle meshes with z = 0 and "
                "tetrahedral meshes), line " +
                std::to_string(content.first_nonzero_z_line));
  }
  return 2;
}

std::string list_keyword(const MshElementBlock& list) {
  return list.type == nullptr ? "$Elements" : "$Elements (" + std::string(list.type->name) + ")";
}

template <int D>
MeshFileContent assemble(MshContent&& content, const std::string& path) {
  RawMesh<D> raw;
  if constexpr (D == 3) {
    raw.nodes = std::move(content.nodes);
  } else {
    raw.nodes.reserve(content.nodes.size());
    for (const Vec3& node : content.nodes) raw.nodes.push_back({{node[0], node[1]}});
  }
  raw.node_refs.assign(raw.nodes.size(), 0);
  MshElementBlock &elements = content.lists[D], &facets = content.lists[D - 1], &points = content.lists[0];
  raw.order = elements.type->order;
  raw.element_keyword = list_keyword(elements);
  raw.element_nodes = std::move(elements.nodes);
  raw.element_refs = std::move(elements.refs);
  auto order_of = [&](const MshElementBlock& list) {
    int order = list.type == nullptr ? 1 : list.type->order;
    if (order > raw.order)
      throw Error(path + ": " + list_keyword(list) + ": P2 elements of lower dimension in a P1 mesh of " +
                  std::string(elements.type->name));
    return order;
  };
  raw.facet_order = order_of(facets);
  raw.facet_keyword = list_keyword(facets);
  raw.facet_nodes = std::move(facets.nodes);
  raw.facet_refs = std::move(facets.refs);
  if constexpr (D == 3) {
    MshElementBlock& lines = content.lists[1];
    raw.line_order = order_of(lines);
    raw.line_keyword = list_keyword(lines);
    raw.line_nodes = std::move(lines.nodes);
    raw.line_refs = std::move(lines.refs);
  }
  // Points carry their ref to their node, so a corner's vertex ref survives a round trip.
  for (std::size_t i = 0; i < points.nodes.size(); ++i) raw.node_refs[points.nodes[i]] = points.refs[i];
  raw.corners = std::move(points.nodes);
  return assemble_mesh(std::move(raw), path);
}

// One kind of entity written (points, lines, facets or elements), grouped by ref: Gmsh entity
// i + 1 holds the entities by_ref[entity_begin[i] .. entity_begin[i + 1]), all of one ref, in
// mesh order.
struct WrittenGroup {
  const ElementType* type = nullptr;
  // The node ids of an entity in hocav's local order (file numbering: vertices, then edge nodes).
  std::function<void(Index, Index*)> nodes;
  std::vector<int> refs;
  std::vector<Index> by_ref;
  std::vector<std::size_t> entity_begin;

  WrittenGroup() = default;
  WrittenGroup(const ElementType& element_type, Index count, const std::function<int(Index)>& ref,
               std::function<void(Index, Index*)> node_ids)
      : type(&element_type), nodes(std::move(node_ids)), refs(static_cast<std::size_t>(count)) {
    for (Index i = 0; i < count; ++i) refs[i] = ref(i);
    by_ref.resize(refs.size());
    std::iota(by_ref.begin(), by_ref.end(), 0);
    std::stable_sort(by_ref.begin(), by_ref.end(), [&](Index a, Index b) { return refs[a] < refs[b]; });
    for (std::size_t i = 0; i < by_ref.size(); ++i)
      if (i == 0 || refs[by_ref[i]] != refs[by_ref[i - 1]]) entity_begin.push_back(i);
    entity_begin.push_back(by_ref.size());
  }

  std::size_t entity_count() const { return entity_begin.empty() ? 0 : entity_begin.size() - 1; }
  int entity_ref(std::size_t entity) const { return refs[by_ref[entity_begin[entity]]]; }
};

// The groups by dimension (points, lines, facets, elements); absent ones have no type.
template <int D>
std::array<WrittenGroup, 4> written_groups(const Mesh<D>& mesh) {
  const int order = mesh.order();
  const Index vertex_count = mesh.vertex_count();
  auto edge_node = [&mesh, vertex_count](Index a, Index b) { return vertex_count + mesh.find_edge(a, b); };
  std::array<WrittenGroup, 4> groups;
  // Corners have no ref of their own: their vertex ref stands in.
  groups[0] = WrittenGroup(
      element_type(0, 1), static_cast<Index>(mesh.corners().size()), [&mesh](Index i) { return mesh.vertex_ref(mesh.corners()[i]); },
      [&mesh](Index i, Index* nodes) { nodes[0] = mesh.corners()[i]; });
  groups[D] = WrittenGroup(
      element_type(D, order), mesh.element_count(), [&mesh](Index k) { return mesh.element_ref(k); },
      [&mesh, order, vertex_count](Index k, Index* nodes) {
        std::copy(mesh.element(k).begin(), mesh.element(k).end(), nodes);
        if (order == 2)
          for (int e = 0; e < Simplex<D>::kEdges; ++e) nodes[D + 1 + e] = vertex_count + mesh.element_edge(k, e);
      });
  groups[D - 1] = WrittenGroup(
      element_type(D - 1, order), mesh.facet_count(), [&mesh](Index f) { return mesh.facet_ref(f); },
      [&mesh, order, edge_node](Index f, Index* nodes) {
        const auto& facet = mesh.facet(f);
        std::copy(facet.begin(), facet.end(), nodes);
        if (order == 2)  // a facet's edges in triangle order; a segment has (0, 1)
          for (int e = 0; e < (D == 3 ? 3 : 1); ++e) nodes[D + e] = edge_node(facet[edge_vertices<2>(e)[0]], facet[edge_vertices<2>(e)[1]]);
      });
  if constexpr (D == 3)
    groups[1] = WrittenGroup(
        element_type(1, order), mesh.line_count(), [&mesh](Index l) { return mesh.line_ref(l); },
        [&mesh, order, edge_node](Index l, Index* nodes) {
          nodes[0] = mesh.line(l)[0];
          nodes[1] = mesh.line(l)[1];
          if (order == 2) nodes[2] = edge_node(nodes[0], nodes[1]);
        });
  return groups;
}

// The entities of each dimension by ref, each point entity at its first point, in the bounding box
// of every node.
template <int D>
void write_entities(TextWriter& out, const Mesh<D>& mesh, const std::array<WrittenGroup, 4>& groups) {
  Vec<D> low, high;
  if (mesh.vertex_count() > 0) low = high = mesh.vertex(0);
  auto extend = [&low, &high](const Vec<D>& point) {
    for (int c = 0; c < D; ++c) {
      low[c] = std::min(low[c], point[c]);
      high[c] = std::max(high[c], point[c]);
    }
  };
  for (const auto& vertex : mesh.vertices()) extend(vertex);
  for (Index e = 0; mesh.is_p2() && e < mesh.edge_count(); ++e) extend(mesh.edge_node(e));
  std::array<std::vector<int>, 4> refs;
  std::vector<Vec<D>> points;
  for (int dimension = 0; dimension < 4; ++dimension) {
    const WrittenGroup& group = groups[dimension];
    for (std::size_t entity = 0; entity < group.entity_count(); ++entity) {
      refs[dimension].push_back(group.entity_ref(entity));
      if (dimension > 0) continue;
      Index node;
      group.nodes(group.by_ref[group.entity_begin[entity]], &node);
      points.push_back(mesh.vertex(node));
    }
  }
  gmsh_msh::write_entities(out, refs, points, low, high);
}

template <int D>
void write_nodes(TextWriter& out, const Mesh<D>& mesh) {
  const Index node_count = mesh.vertex_count() + (mesh.is_p2() ? mesh.edge_count() : 0);
  gmsh_msh::write_nodes_head(out, D, node_count);
  if (node_count == 0) return;
  for (Index node = 1; node <= node_count; ++node) out << node << '\n';
  for (const auto& vertex : mesh.vertices()) {
    gmsh_msh::write_point(out, vertex);
    out << '\n';
  }
  for (Index e = 0; mesh.is_p2() && e < mesh.edge_count(); ++e) {
    gmsh_msh::write_point(out, mesh.edge_node(e));
    out << '\n';
  }
  out << "$EndNodes\n";
}

void write_elements(TextWriter& out, const std::array<WrittenGroup, 4>& groups) {
  std::size_t block_count = 0, element_count = 0;
  for (const WrittenGroup& group : groups) {
    block_count += group.entity_count();
    element_count += group.by_ref.size();
  }
  gmsh_msh::write_elements_head(out, block_count, element_count);
  std::size_t tag = 1;
  std::array<Index, 10> nodes;
  for (const WrittenGroup& group : groups)
    for (std::size_t entity = 0; entity < group.entity_count(); ++entity) {
      std::size_t begin = group.entity_begin[entity], end = group.entity_begin[entity + 1];
      gmsh_msh::write_block_head(out, entity + 1, *group.type, end - begin);
      for (std::size_t i = begin; i < end; ++i) {
        group.nodes(group.by_ref[i], nodes.data());
        gmsh_msh::write_element(out, tag++, *group.type, nodes.data());
      }
    }
  out << "$EndElements\n";
}

}  // namespace

MeshFileContent read_gmsh_msh(const std::string& path) {
  MshContent content = MshReader(path).read();
  return mesh_dimension(content, path) == 3 ? assemble<3>(std::move(content), path) : assemble<2>(std::move(content), path);
}

int gmsh_msh_dimension(const std::string& path) { return mesh_dimension(MshReader(path).read(), path); }

template <int D>
void write_gmsh_msh(const std::string& path, const Mesh<D>& mesh) {
  std::array<WrittenGroup, 4> groups = written_groups(mesh);
  AtomicOutput output(path);
  TextWriter out(output.stream());
  out << gmsh_msh::kMeshFormat;
  write_entities(out, mesh, groups);
  write_nodes(out, mesh);
  write_elements(out, groups);
  out.flush();
  output.commit();
}

template void write_gmsh_msh(const std::string&, const Mesh<2>&);
template void write_gmsh_msh(const std::string&, const Mesh<3>&);

}  // namespace hocav
