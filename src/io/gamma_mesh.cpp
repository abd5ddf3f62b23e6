// Gamma/Medit meshes. Reading goes file -> MeshRecords (what the keywords hold, in file numbering)
// -> RawMesh<D> (node lists in hocav's local order) -> assemble_mesh; the keyword parsing is written
// once over the ASCII and binary keyword readers, the writing once over the two writers.
#include "io/gamma_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/error.hpp"
#include "io/gamma_keyword_reader.hpp"
#include "io/gamma_keyword_writer.hpp"
#include "io/gamma_keywords.hpp"
#include "io/mesh_assembly.hpp"
#include "mesh/simplex.hpp"

namespace hocav {
namespace {

using gamma::SimplexKeyword;

// Node lists of one simplex keyword, 0-based file node ids in the file's node order.
struct NodeTable {
  std::vector<Index> nodes;
  std::vector<int> refs;
  Index first = 0, total = 0;  // the file id of the first entity kept; the keyword's count
};

// The run of records a reader keeps of the large keywords (vertices, elements, facets): run `index`
// of `count` runs of consecutive records of nearly equal length; every record by default.
struct MeshRecords {
  std::vector<double> coordinates;  // `dimension` reals per kept file node
  std::vector<int> node_refs;
  Index first_node = 0, node_total = 0;       // the file id of the first node kept; the file's node count
  std::map<int, NodeTable> simplices;         // by keyword code
  std::map<int, std::vector<int>> orderings;  // by ordering keyword code: a Bézier index row per node
  std::vector<Index> corners, ridges, required_vertices, required_edges, required_triangles;
};

// The width of a row of an ordering keyword, as libMeshb defines them: the full Bézier multi-index
// for triangles and tetrahedra, a single integer (the weight of the first vertex) for edges.
int ordering_width(const SimplexKeyword& keyword) { return keyword.simplex_dimension == 1 ? 1 : keyword.simplex_dimension + 1; }

// ---- reading keywords (Reader: gamma::TextKeywordReader or gamma::BinaryKeywordReader) ----

// A 1-based id of the file, returned 0-based.
template <class Reader>
Index read_id(Reader& reader, Index entity, const char* what) {
  std::int64_t id = reader.read_integer(entity);
  if (id < 1 || id > std::numeric_limits<Index>::max()) reader.fail(std::string(what) + " " + std::to_string(id) + " out of range", entity);
  return static_cast<Index>(id - 1);
}

template <class Reader>
int read_ref(Reader& reader, Index entity) {
  std::int64_t ref = reader.read_integer(entity);
  if (ref < std::numeric_limits<int>::min() || ref > std::numeric_limits<int>::max())
    reader.fail("reference " + std::to_string(ref) + " out of range", entity);
  return static_cast<int>(ref);
}

template <class Reader>
void read_vertices(Reader& reader, MeshRecords& records, const RecordRun& slice) {
  const int dimension = reader.dimension();
  if (dimension == 0) reader.fail("no Dimension before the vertices");
  const Index count = reader.read_count();
  reader.expect_records(count, 1, dimension);
  const auto [first, last] = slice.of(count);
  records.first_node = first;
  records.node_total = count;
  reader.skip_records(first, 1, dimension);
  records.coordinates.reserve(reader.reserve_hint(last - first) * dimension);
  records.node_refs.reserve(reader.reserve_hint(last - first));
  for (Index v = first; v < last; ++v) {
    for (int i = 0; i < dimension; ++i) {
      double x = reader.read_real(v);
      if (!std::isfinite(x)) reader.fail("coordinate is not finite", v);
      records.coordinates.push_back(x);
    }
    records.node_refs.push_back(read_ref(reader, v));
  }
  reader.skip_records(count - last, 1, dimension);
}

template <class Reader>
void read_simplices(Reader& reader, const SimplexKeyword& keyword, NodeTable& table, const RecordRun& slice) {
  const Index count = reader.read_count();
  reader.expect_records(count, keyword.node_count + 1, 0);
  const auto [first, last] = slice.of(count);
  table.first = first;
  table.total = count;
  reader.skip_records(first, keyword.node_count + 1, 0);
  table.nodes.reserve(reader.reserve_hint(last - first) * keyword.node_count);
  table.refs.reserve(reader.reserve_hint(last - first));
  for (Index k = first; k < last; ++k) {
    for (int i = 0; i < keyword.node_count; ++i) table.nodes.push_back(read_id(reader, k, "vertex"));
    table.refs.push_back(read_ref(reader, k));
  }
  reader.skip_records(count - last, keyword.node_count + 1, 0);
}

template <class Reader>
void read_id_list(Reader& reader, std::vector<Index>& ids, const char* what) {
  const Index count = reader.read_count();
  reader.expect_records(count, 1, 0);
  ids.reserve(reader.reserve_hint(count));
  for (Index i = 0; i < count; ++i) ids.push_back(read_id(reader, i, what));
}

template <class Reader>
void read_ordering(Reader& reader, const SimplexKeyword& keyword, std::vector<int>& rows) {
  const Index count = reader.read_count();
  if (count != keyword.node_count)
    reader.fail("lists " + std::to_string(count) + " nodes, " + gamma::keyword_name(keyword.code) + " has " +
                std::to_string(keyword.node_count));
  const int width = ordering_width(keyword);
  reader.expect_records(count, width, 0);
  for (Index node = 0; node < count; ++node)
    for (int i = 0; i < width; ++i) {
      std::int64_t index = reader.read_integer(node);
      if (index < 0 || index > keyword.order) reader.fail("Bézier index " + std::to_string(index) + " out of range", node);
      rows.push_back(static_cast<int>(index));
    }
}

// With a slice, the vertices, elements and facets are kept in that slice's run; the feature lines
// (3D) and the tag lists whole.
template <class Reader>
MeshRecords read_records(Reader& reader, const RecordRun& slice = {}) {
  MeshRecords records;
  std::set<int> seen;
  while (reader.next_keyword()) {
    const int code = reader.keyword_code();
    const SimplexKeyword* simplex = gamma::simplex_keyword(code);
    const SimplexKeyword* ordered = gamma::ordered_keyword(code);
    const bool read = simplex || ordered || code == gamma::kVertices || code == gamma::kCorners || code == gamma::kRidges ||
                      code == gamma::kRequiredVertices || code == gamma::kRequiredEdges || code == gamma::kRequiredTriangles;
    if (!read) {
      if (gamma::is_unsupported_element(code)) reader.fail("element kind not supported (hocav reads triangles and tetrahedra)");
      reader.skip_keyword();
      continue;
    }
    if (!seen.insert(code).second) reader.fail("keyword appears twice");
    if (simplex)
      read_simplices(reader, *simplex, records.simplices[code], simplex->simplex_dimension + 1 >= reader.dimension() ? slice : RecordRun{});
    else if (ordered)
      read_ordering(reader, *ordered, records.orderings[code]);
    else if (code == gamma::kVertices)
      read_vertices(reader, records, slice);
    else if (code == gamma::kCorners)
      read_id_list(reader, records.corners, "vertex");
    else if (code == gamma::kRidges)
      read_id_list(reader, records.ridges, "edge");
    else if (code == gamma::kRequiredVertices)
      read_id_list(reader, records.required_vertices, "vertex");
    else if (code == gamma::kRequiredEdges)
      read_id_list(reader, records.required_edges, "edge");
    else
      read_id_list(reader, records.required_triangles, "triangle");
  }
  return records;
}

// ---- records -> RawMesh ----

// The Bézier multi-index of a P2 node in hocav's local order: vertex i is 2 e_i, the node of local
// edge (a, b) is e_a + e_b.
std::array<int, 4> local_multi_index(int simplex_dimension, int local_node) {
  std::array<int, 4> index{};
  if (local_node <= simplex_dimension) {
    index[static_cast<std::size_t>(local_node)] = 2;
    return index;
  }
  int edge = local_node - simplex_dimension - 1;
  std::array<int, 2> ends = simplex_dimension == 1   ? std::array<int, 2>{0, 1}
                            : simplex_dimension == 2 ? edge_vertices<2>(edge)
                                                     : edge_vertices<3>(edge);
  index[static_cast<std::size_t>(ends[0])] = index[static_cast<std::size_t>(ends[1])] = 1;
  return index;
}

// Puts the node lists of a P2 keyword, given in the order of its *P2Ordering rows, into hocav's
// local order.
void apply_ordering(std::vector<Index>& nodes, const SimplexKeyword& keyword, const std::vector<int>& rows, const std::string& path) {
  const int count = keyword.node_count, width = ordering_width(keyword);
  std::vector<int> file_position(static_cast<std::size_t>(count), -1);
  bool identity = true;
  for (int local = 0; local < count; ++local) {
    std::array<int, 4> wanted = local_multi_index(keyword.simplex_dimension, local);
    for (int row = 0; row < count && file_position[local] < 0; ++row)
      if (std::equal(wanted.begin(), wanted.begin() + width, rows.begin() + row * width)) file_position[local] = row;
    if (file_position[local] < 0)
      throw Error(path + ": " + gamma::keyword_name(keyword.ordering_code) + ": the rows are not a permutation of the " +
                  std::to_string(count) + " P2 nodes");
    identity = identity && file_position[local] == local;
  }
  if (identity) return;
  std::vector<Index> entity(static_cast<std::size_t>(count));
  for (std::size_t start = 0; start < nodes.size(); start += entity.size()) {
    for (int local = 0; local < count; ++local) entity[local] = nodes[start + file_position[local]];
    std::copy(entity.begin(), entity.end(), nodes.begin() + static_cast<std::ptrdiff_t>(start));
  }
}

// The keyword that holds the simplices of a dimension (P1 or P2), or nullptr when there are none.
const SimplexKeyword* present_keyword(const MeshRecords& records, int simplex_dimension, const std::string& path) {
  auto present = [&](const SimplexKeyword& keyword) {
    auto table = records.simplices.find(keyword.code);
    return table != records.simplices.end() && !table->second.refs.empty();
  };
  const SimplexKeyword& p1 = gamma::simplex_keyword(simplex_dimension, 1);
  const SimplexKeyword& p2 = gamma::simplex_keyword(simplex_dimension, 2);
  if (present(p1) && present(p2))
    throw Error(path + ": " + gamma::keyword_name(p1.code) + " and " + gamma::keyword_name(p2.code) +
                ": mixing P1 and P2 entities of one kind is not supported");
  return present(p1) ? &p1 : present(p2) ? &p2 : nullptr;
}

void take_nodes(MeshRecords& records, const SimplexKeyword& keyword, const std::string& path, std::vector<Index>& nodes,
                std::vector<int>& refs) {
  NodeTable& table = records.simplices[keyword.code];
  nodes = std::move(table.nodes);
  refs = std::move(table.refs);
  auto ordering = records.orderings.find(keyword.ordering_code);
  if (keyword.order == 2 && ordering != records.orderings.end()) apply_ordering(nodes, keyword, ordering->second, path);
}

template <int D>
MeshFileContent build_mesh(MeshRecords&& records, const std::string& path) {
  if (const SimplexKeyword* volume = D == 2 ? present_keyword(records, 3, path) : nullptr)
    throw Error(path + ": " + gamma::keyword_name(volume->code) + ": tetrahedra in a mesh of Dimension 2");
  const SimplexKeyword* element = present_keyword(records, D, path);
  if (!element) {
    if (D == 3 && present_keyword(records, 2, path))
      throw Error(path +
                  ": Triangles: surface meshes (triangles without tetrahedra in Dimension 3) are not supported; a planar mesh "
                  "must say Dimension 2 (gmsh writes its 2D .mesh files with Dimension 3: save them as .msh, read as 2D when z = 0)");
    throw Error(path + ": no " + gamma::keyword_name(gamma::simplex_keyword(D, 1).code) + " or " +
                gamma::keyword_name(gamma::simplex_keyword(D, 2).code) + ": hocav reads meshes of a " + std::to_string(D) + "D domain");
  }
  const SimplexKeyword* facet = present_keyword(records, D - 1, path);
  const SimplexKeyword* line = D == 3 ? present_keyword(records, 1, path) : nullptr;
  for (const SimplexKeyword* boundary : {facet, line})
    if (boundary && boundary->order > element->order)
      throw Error(path + ": " + gamma::keyword_name(boundary->code) + ": P2 entities in a P1 mesh (" + gamma::keyword_name(element->code) +
                  ")");

  RawMesh<D> raw;
  const std::size_t node_count = records.node_refs.size();
  raw.nodes.resize(node_count);
  for (std::size_t node = 0; node < node_count; ++node)
    for (int i = 0; i < D; ++i) raw.nodes[node][i] = records.coordinates[node * D + i];
  records.coordinates = {};
  raw.node_refs = std::move(records.node_refs);
  raw.order = element->order;
  raw.element_keyword = gamma::keyword_name(element->code);
  take_nodes(records, *element, path, raw.element_nodes, raw.element_refs);
  if (facet) {
    raw.facet_order = facet->order;
    raw.facet_keyword = gamma::keyword_name(facet->code);
    take_nodes(records, *facet, path, raw.facet_nodes, raw.facet_refs);
  }
  if (line) {
    raw.line_order = line->order;
    raw.line_keyword = gamma::keyword_name(line->code);
    take_nodes(records, *line, path, raw.line_nodes, raw.line_refs);
  }
  raw.corners = std::move(records.corners);
  raw.ridges = std::move(records.ridges);
  raw.required_vertices = std::move(records.required_vertices);
  raw.required_edges = std::move(records.required_edges);
  raw.required_triangles = std::move(records.required_triangles);
  return assemble_mesh(std::move(raw), path);
}

template <class Reader>
std::pair<int, MeshRecords> read_file(Reader&& reader, const RecordRun& slice = {}) {
  MeshRecords records = read_records(reader, slice);
  if (reader.dimension() == 0) throw Error(reader.path() + ": Dimension: missing");
  return {reader.dimension(), std::move(records)};
}

// Reads no further than the Dimension keyword (usually the first).
template <class Reader>
int declared_dimension(Reader&& reader) {
  while (reader.dimension() == 0 && reader.next_keyword())
    if (reader.dimension() == 0) reader.skip_keyword(false);
  if (reader.dimension() == 0) throw Error(reader.path() + ": Dimension: missing");
  return reader.dimension();
}

template <class Reader>
bool has_p2_keyword(Reader&& reader) {
  while (reader.next_keyword()) {
    const SimplexKeyword* simplex = gamma::simplex_keyword(reader.keyword_code());
    if (simplex && simplex->order == 2) return true;
    reader.skip_keyword(false);
  }
  return false;
}

// ---- writing (Writer: gamma::TextKeywordWriter or gamma::BinaryKeywordWriter) ----

std::array<int, 2> local_edge(int simplex_dimension, int edge) {
  if (simplex_dimension == 1) return {0, 1};
  return simplex_dimension == 2 ? edge_vertices<2>(edge) : edge_vertices<3>(edge);
}

template <int D, class Writer>
void write_records(Writer& out, const Mesh<D>& mesh, const std::string& path) {
  const bool p2 = mesh.is_p2();
  const std::int64_t vertex_count = mesh.vertex_count();
  out.begin_keyword(gamma::kVertices, vertex_count + (p2 ? mesh.edge_count() : 0), 1, D);
  auto write_node = [&](const Vec<D>& point, int ref) {
    for (int i = 0; i < D; ++i) out.write_real(point[i]);
    out.write_integer(ref);
    out.end_record();
  };
  for (Index v = 0; v < mesh.vertex_count(); ++v) write_node(mesh.vertex(v), mesh.vertex_ref(v));
  if (p2)
    for (Index e = 0; e < mesh.edge_count(); ++e) write_node(mesh.edge_node(e), 0);

  // File node number (1-based) of the P2 node of an edge found from its vertices.
  auto edge_node_of = [&](Index a, Index b) {
    Index edge = mesh.find_edge(a, b);
    if (edge == kNoIndex) throw Error(path + ": edge (" + one_based(a) + ", " + one_based(b) + ") has no P2 node");
    return vertex_count + edge + 1;
  };
  // vertices_of(k): the entity's vertices; mid_node_of(k, vertices, local edge): its edge's node.
  auto write_simplices = [&](int simplex_dimension, Index count, auto vertices_of, auto ref_of, auto mid_node_of) {
    if (count == 0) return;
    const SimplexKeyword& keyword = gamma::simplex_keyword(simplex_dimension, mesh.order());
    out.begin_keyword(keyword.code, count, keyword.node_count + 1, 0);
    for (Index k = 0; k < count; ++k) {
      const auto& vertices = vertices_of(k);
      for (Index v : vertices) out.write_integer(v + 1);
      for (int e = 0; e < keyword.node_count - simplex_dimension - 1; ++e) out.write_integer(mid_node_of(k, vertices, e));
      out.write_integer(ref_of(k));
      out.end_record();
    }
  };
  auto mid_node_by_search = [&](Index, const auto& vertices, int e) {
    const std::array<int, 2> ends = local_edge(static_cast<int>(vertices.size()) - 1, e);
    return edge_node_of(vertices[ends[0]], vertices[ends[1]]);
  };
  // By dimension, as Gamma files usually are: (3D) feature lines, facets, elements.
  if constexpr (D == 3)
    write_simplices(
        1, mesh.line_count(), [&](Index l) -> const auto& { return mesh.line(l); }, [&](Index l) { return mesh.line_ref(l); },
        mid_node_by_search);
  write_simplices(
      D - 1, mesh.facet_count(), [&](Index f) -> const auto& { return mesh.facet(f); }, [&](Index f) { return mesh.facet_ref(f); },
      mid_node_by_search);
  write_simplices(
      D, mesh.element_count(), [&](Index k) -> const auto& { return mesh.element(k); }, [&](Index k) { return mesh.element_ref(k); },
      [&](Index k, const auto&, int e) { return vertex_count + mesh.element_edge(k, e) + 1; });

  auto write_ids = [&](int code, const std::vector<Index>& ids) {
    if (ids.empty()) return;
    out.begin_keyword(code, static_cast<std::int64_t>(ids.size()), 1, 0);
    for (Index id : ids) {
      out.write_integer(id + 1);
      out.end_record();
    }
  };
  write_ids(gamma::kCorners, mesh.corners());
  write_ids(gamma::kRidges, mesh.ridges());
  write_ids(gamma::kRequiredVertices, mesh.required_vertices());
  write_ids(gamma::kRequiredEdges, mesh.required_edges());
  write_ids(gamma::kRequiredTriangles, mesh.required_triangles());
}

// The entities of the P1 simplex keyword of N vertices, as file vertex ids, checked against the
// file's vertex count.
template <std::size_t N>
std::vector<std::array<Index, N>> checked_entities(const NodeTable& table, Index vertex_count, const std::string& path) {
  const int simplex_dimension = static_cast<int>(N) - 1;
  std::vector<std::array<Index, N>> entities(table.refs.size());
  for (std::size_t k = 0; k < entities.size(); ++k)
    for (std::size_t i = 0; i < N; ++i) {
      entities[k][i] = table.nodes[k * N + i];
      if (entities[k][i] >= vertex_count)
        throw Error(path + ": " + gamma::keyword_name(gamma::simplex_keyword(simplex_dimension, 1).code) + ": vertex " +
                    one_based(entities[k][i]) + " out of range, entity " + std::to_string(table.first + static_cast<Index>(k) + 1));
    }
  return entities;
}

// Throws Error naming the first element of the run (the file's from `first`) that repeats a vertex,
// in the words of the whole file's reader (mesh_assembly.cpp).
template <std::size_t N>
void refuse_repeated_vertices(const std::vector<std::array<Index, N>>& elements, Index first, const std::string& path) {
  for (std::size_t k = 0; k < elements.size(); ++k)
    if (repeats_a_vertex(elements[k]))
      throw Error(path + ": " + gamma::keyword_name(gamma::simplex_keyword(static_cast<int>(N) - 1, 1).code) +
                  ": repeats a vertex in element " + std::to_string(first + static_cast<Index>(k) + 1));
}

}  // namespace

MeshFileContent read_gamma_mesh(const std::string& path) {
  auto [dimension, records] = gamma::is_binary_file(path) ? read_file(gamma::BinaryKeywordReader(path))
                                                          : read_file(gamma::TextKeywordReader(path));
  return dimension == 2 ? build_mesh<2>(std::move(records), path) : build_mesh<3>(std::move(records), path);
}

template <int D>
GammaMeshSlice<D> read_gamma_mesh_slice(const std::string& path, int index, int count) {
  const RecordRun slice{index, count};
  auto read = [&](auto&& reader) {
    if (index != 0) reader.silence_warnings();  // slice 0 warns for every slice
    return read_file(reader, slice);
  };
  // (Not a structured binding: clang before 16 lets no lambda capture one.)
  std::pair<int, MeshRecords> file = gamma::is_binary_file(path) ? read(gamma::BinaryKeywordReader(path))
                                                                 : read(gamma::TextKeywordReader(path));
  const int dimension = file.first;
  MeshRecords& records = file.second;
  if (dimension != D) throw Error(path + ": Dimension: " + std::to_string(dimension) + ", not " + std::to_string(D));
  for (const auto& [code, table] : records.simplices)
    if (gamma::simplex_keyword(code)->order == 2 && !table.refs.empty())
      throw Error(path + ": " + gamma::keyword_name(code) + ": a distributed run reads P1 meshes in pieces; P2 entities are not read so");
  GammaMeshSlice<D> out;
  out.vertex_count = records.node_total;
  out.first_vertex = records.first_node;
  for (std::size_t v = 0; v < records.node_refs.size(); ++v) {
    Vec<D> point;
    for (int i = 0; i < D; ++i) point[i] = records.coordinates[v * D + static_cast<std::size_t>(i)];
    out.points.push_back(point);
  }
  out.point_refs = std::move(records.node_refs);
  auto take = [&]<std::size_t N>(std::vector<std::array<Index, N>>& entities, std::vector<int>& refs, Index& first, Index& total) {
    NodeTable& table = records.simplices[gamma::simplex_keyword(static_cast<int>(N) - 1, 1).code];
    entities = checked_entities<N>(table, out.vertex_count, path);
    refs = std::move(table.refs);
    first = table.first;
    total = table.total;
  };
  take(out.elements, out.element_refs, out.first_element, out.element_count);
  refuse_repeated_vertices(out.elements, out.first_element, path);
  take(out.facets, out.facet_refs, out.first_facet, out.facet_count);
  if constexpr (D == 3) {
    Index first = 0, total = 0;
    take(out.lines, out.line_refs, first, total);
  }
  if (out.element_count == 0) throw Error(path + ": no " + gamma::keyword_name(gamma::simplex_keyword(D, 1).code));
  out.corners = std::move(records.corners);
  out.ridges = std::move(records.ridges);
  out.required_vertices = std::move(records.required_vertices);
  out.required_edges = std::move(records.required_edges);
  out.required_triangles = std::move(records.required_triangles);
  return out;
}

template GammaMeshSlice<2> read_gamma_mesh_slice(const std::string&, int, int);
template GammaMeshSlice<3> read_gamma_mesh_slice(const std::string&, int, int);

int gamma_mesh_dimension(const std::string& path) {
  return gamma::is_binary_file(path) ? declared_dimension(gamma::BinaryKeywordReader(path))
                                     : declared_dimension(gamma::TextKeywordReader(path));
}

bool gamma_mesh_has_p2_keyword(const std::string& path) {
  return gamma::is_binary_file(path) ? has_p2_keyword(gamma::BinaryKeywordReader(path)) : has_p2_keyword(gamma::TextKeywordReader(path));
}

template <int D>
void write_gamma_mesh(const std::string& path, const Mesh<D>& mesh, bool binary, int version) {
  const std::int64_t largest_node = std::int64_t{mesh.vertex_count()} + (mesh.is_p2() ? mesh.edge_count() : 0);
  if (binary) {
    gamma::BinaryKeywordWriter out(path, gamma::resolve_version(path, version, largest_node, 3), D);
    write_records(out, mesh, path);
    out.finish();
  } else {
    gamma::TextKeywordWriter out(path, gamma::resolve_version(path, version, largest_node, 2), D);
    write_records(out, mesh, path);
    out.finish();
  }
}

template void write_gamma_mesh(const std::string&, const Mesh<2>&, bool, int);
template void write_gamma_mesh(const std::string&, const Mesh<3>&, bool, int);

}  // namespace hocav
