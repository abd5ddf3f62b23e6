#include "io/mesh_assembly.hpp"

#include <string>

#include "base/error.hpp"
#include "mesh/simplex.hpp"

namespace hocav {
namespace {

template <int D>
class Assembler {
 public:
  Assembler(RawMesh<D>& raw, const std::string& path) : raw_(raw), path_(path) {}

  MeshFileContent run() {
    const int element_size = (D + 1) + (raw_.order == 2 ? Simplex<D>::kEdges : 0);
    const int facet_size = D + (raw_.facet_order == 2 ? (D == 3 ? 3 : 1) : 0);
    const int line_size = 2 + (raw_.line_order == 2 ? 1 : 0);
    check_sizes(raw_.element_nodes, element_size, raw_.element_keyword);
    check_sizes(raw_.facet_nodes, facet_size, raw_.facet_keyword);
    check_sizes(raw_.line_nodes, line_size, raw_.line_keyword);

    // Every node that is not a mid-edge node becomes a vertex (unused nodes included, so a P1
    // file keeps its numbering), in file order.
    file_to_vertex_.assign(raw_.nodes.size(), 0);
    mark_mid_nodes(raw_.element_nodes, element_size, D + 1);
    mark_mid_nodes(raw_.facet_nodes, facet_size, D);
    mark_mid_nodes(raw_.line_nodes, line_size, 2);
    Mesh<D> mesh;
    MeshFileContent content{Mesh<D>{}, {}, {}, checked_index(raw_.nodes.size(), "nodes")};
    for (std::size_t node = 0; node < raw_.nodes.size(); ++node)
      if (file_to_vertex_[node] != kNoIndex) {
        file_to_vertex_[node] = mesh.add_vertex(raw_.nodes[node], raw_.node_refs[node]);
        content.vertex_file_ids.push_back(static_cast<Index>(node));
      }

    for (std::size_t k = 0; k * element_size < raw_.element_nodes.size(); ++k) {
      typename Mesh<D>::Element element;
      for (int i = 0; i <= D; ++i) element[i] = vertex_of(raw_.element_nodes[k * element_size + i], raw_.element_keyword, k);
      if (repeats_a_vertex(element)) fail(raw_.element_keyword, "repeats a vertex in element", k);
      mesh.add_element(element, raw_.element_refs[k]);
    }
    for (std::size_t f = 0; f * facet_size < raw_.facet_nodes.size(); ++f) {
      typename Mesh<D>::Facet facet;
      for (int i = 0; i < D; ++i) facet[i] = vertex_of(raw_.facet_nodes[f * facet_size + i], raw_.facet_keyword, f);
      mesh.add_facet(facet, raw_.facet_refs[f]);
    }
    if constexpr (D == 3)
      for (std::size_t l = 0; l * line_size < raw_.line_nodes.size(); ++l)
        mesh.add_line({vertex_of(raw_.line_nodes[l * line_size], raw_.line_keyword, l),
                       vertex_of(raw_.line_nodes[l * line_size + 1], raw_.line_keyword, l)},
                      raw_.line_refs[l]);
    for (std::size_t i = 0; i < raw_.corners.size(); ++i) mesh.corners().push_back(vertex_of(raw_.corners[i], "Corners", i));
    for (std::size_t i = 0; i < raw_.required_vertices.size(); ++i)
      mesh.required_vertices().push_back(vertex_of(raw_.required_vertices[i], "RequiredVertices", i));
    const Index edge_entities = D == 2 ? mesh.facet_count() : mesh.line_count();
    take_ids(raw_.ridges, edge_entities, "Ridges", "names no edge in ridge", mesh.ridges());
    take_ids(raw_.required_edges, edge_entities, "RequiredEdges", "names no edge in required edge", mesh.required_edges());
    // A 2D mesh's triangles are its elements, which adaptation and curving renumber: not kept.
    if (D == 2 && !raw_.required_triangles.empty()) fail("RequiredTriangles", "not supported in a 2D mesh (its elements), entry", 0);
    take_ids(raw_.required_triangles, mesh.facet_count(), "RequiredTriangles", "names no triangle in required triangle",
             mesh.required_triangles());

    try {
      mesh.build_topology();
    } catch (const Error& error) {
      throw Error(path_ + ": " + error.what());
    }
    if (raw_.order == 2) assign_p2_nodes(mesh, content, element_size, facet_size, line_size);
    content.mesh = std::move(mesh);
    return content;
  }

 private:
  // Checks each id is below `count` and appends it to `out`.
  void take_ids(const std::vector<Index>& ids, Index count, const std::string& keyword, const std::string& what,
                std::vector<Index>& out) const {
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (ids[i] < 0 || ids[i] >= count) fail(keyword, what, i);
      out.push_back(ids[i]);
    }
  }

  [[noreturn]] void fail(const std::string& keyword, const std::string& what, std::size_t entity) const {
    throw Error(path_ + ": " + keyword + ": " + what + " " + one_based(entity));
  }

  void check_sizes(const std::vector<Index>& nodes, int size, const std::string& keyword) const {
    if (nodes.size() % static_cast<std::size_t>(size) != 0) fail(keyword, "incomplete node list at entity", nodes.size() / size);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i] < 0 || static_cast<std::size_t>(nodes[i]) >= raw_.nodes.size())
        fail(keyword, "node " + one_based(nodes[i]) + " out of range in entity", i / size);
  }

  void mark_mid_nodes(const std::vector<Index>& nodes, int size, int corners) {
    for (std::size_t i = 0; i < nodes.size(); i += static_cast<std::size_t>(size))
      for (int m = corners; m < size; ++m) file_to_vertex_[nodes[i + m]] = kNoIndex;
  }

  // The vertex of a file node used as a corner (or tagged); refuses a mid-edge node.
  Index vertex_of(Index node, const std::string& keyword, std::size_t entity) const {
    if (node < 0 || static_cast<std::size_t>(node) >= raw_.nodes.size())
      fail(keyword, "vertex " + one_based(node) + " out of range in entity", entity);
    if (file_to_vertex_[node] == kNoIndex)
      fail(keyword, "node " + one_based(node) + " is both a corner and a mid-edge node, in entity", entity);
    return file_to_vertex_[node];
  }

  // Gives every edge the node its elements name, checking that they all name the same one.
  void assign_p2_nodes(Mesh<D>& mesh, MeshFileContent& content, int element_size, int facet_size, int line_size) {
    mesh.make_p2();
    content.edge_node_file_ids.assign(static_cast<std::size_t>(mesh.edge_count()), kNoIndex);
    auto give = [&](Index a, Index b, Index node, const std::string& keyword, std::size_t entity) {
      Index edge = mesh.find_edge(a, b);
      if (edge == kNoIndex) fail(keyword, "names an edge no element has, in entity", entity);
      Index& known = content.edge_node_file_ids[edge];
      if (known != kNoIndex && known != node)
        fail(keyword, "gives edge (" + one_based(a) + ", " + one_based(b) + ") another mid node, in entity", entity);
      known = node;
      mesh.edge_node(edge) = raw_.nodes[node];
    };
    for (std::size_t k = 0; k * element_size < raw_.element_nodes.size(); ++k)
      for (int e = 0; e < Simplex<D>::kEdges; ++e) {
        const auto& ends = edge_vertices<D>(e);
        const Index* nodes = &raw_.element_nodes[k * element_size];
        give(file_to_vertex_[nodes[ends[0]]], file_to_vertex_[nodes[ends[1]]], nodes[D + 1 + e], raw_.element_keyword, k);
      }
    if (raw_.facet_order == 2)
      for (std::size_t f = 0; f * facet_size < raw_.facet_nodes.size(); ++f) {
        const Index* nodes = &raw_.facet_nodes[f * facet_size];
        for (int e = 0; e < (D == 3 ? 3 : 1); ++e) {
          const auto& ends = edge_vertices<2>(e);  // a facet's edges in triangle order; a segment has (0, 1)
          give(file_to_vertex_[nodes[ends[0]]], file_to_vertex_[nodes[ends[1]]], nodes[D + e], raw_.facet_keyword, f);
        }
      }
    if (raw_.line_order == 2)
      for (std::size_t l = 0; l * line_size < raw_.line_nodes.size(); ++l) {
        const Index* nodes = &raw_.line_nodes[l * line_size];
        give(file_to_vertex_[nodes[0]], file_to_vertex_[nodes[1]], nodes[2], raw_.line_keyword, l);
      }
    for (Index e = 0; e < mesh.edge_count(); ++e)
      if (content.edge_node_file_ids[e] == kNoIndex) fail(raw_.element_keyword, "no mid node given for edge", static_cast<std::size_t>(e));
  }

  RawMesh<D>& raw_;
  const std::string& path_;
  std::vector<Index> file_to_vertex_;
};

}  // namespace

template <int D>
MeshFileContent assemble_mesh(RawMesh<D>&& raw, const std::string& path) {
  if (raw.node_refs.size() != raw.nodes.size()) raw.node_refs.resize(raw.nodes.size(), 0);
  return Assembler<D>(raw, path).run();
}

template MeshFileContent assemble_mesh(RawMesh<2>&&, const std::string&);
template MeshFileContent assemble_mesh(RawMesh<3>&&, const std::string&);

}  // namespace hocav
