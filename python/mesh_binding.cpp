// hocav.Mesh: a 2D or 3D, P1 or P2 mesh. Its arrays are read-only numpy views of the library's
// storage (no copy; each keeps the mesh alive); a Mesh is never changed in place (adapt and curve
// return new ones), so a view stays valid. Made from arrays, it is checked as a file is.
#include <pybind11/stl.h>

#include "base/error.hpp"
#include "binding.hpp"
#include "io/mesh_assembly.hpp"

namespace hocav::python {
namespace {

// A read-only view of `count` rows of `width` values of type T at `data`, kept alive by `owner`.
template <class T>
py::array view(const void* data, std::size_t count, int width, const py::object& owner) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(count)};
  if (width > 0) shape.push_back(width);
  py::array array(py::dtype::of<T>(), shape, static_cast<const T*>(data), owner);
  array.attr("setflags")(py::arg("write") = false);
  return array;
}

py::array points(const py::object& self) {
  return visit_mesh(self.cast<const PyMesh&>(), [&self](const auto& m) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(m)>>;
    static_assert(sizeof(Vec<D>) == D * sizeof(double));
    return view<double>(m.vertices().data(), m.vertices().size(), D, self);
  });
}

py::array elements(const py::object& self) {
  return visit_mesh(self.cast<const PyMesh&>(), [&self](const auto& m) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(m)>>;
    return view<Index>(m.elements().data(), m.elements().size(), D + 1, self);
  });
}

py::array facets(const py::object& self) {
  return visit_mesh(self.cast<const PyMesh&>(), [&self](const auto& m) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(m)>>;
    return view<Index>(m.facets().data(), m.facets().size(), D, self);
  });
}

// Refs of the vertices, elements or facets.
template <class Refs>
py::array refs(const py::object& self, Refs refs_of) {
  return visit_mesh(self.cast<const PyMesh&>(), [&self, &refs_of](const auto& m) {
    const std::span<const int> values = refs_of(m);
    return view<int>(values.data(), values.size(), 0, self);
  });
}

// The P2 nodes: every edge's two vertices, its node, and each element's edges (hocav's local edge order,
// docs/mesh-model.md, which is VTK's and meshio's). Empty on a P1 mesh.
py::array edges(const py::object& self) {
  return visit_mesh(self.cast<const PyMesh&>(),
                    [&self](const auto& m) { return view<Index>(m.edges().data(), m.is_p2() ? m.edges().size() : 0, 2, self); });
}

py::array edge_nodes(const py::object& self) {
  return visit_mesh(self.cast<const PyMesh&>(), [&self](const auto& m) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(m)>>;
    return view<double>(m.edge_nodes().data(), m.is_p2() ? m.edge_nodes().size() : 0, D, self);
  });
}

py::array element_edges(const py::object& self) {
  return visit_mesh(self.cast<const PyMesh&>(), [&self](const auto& m) {
    constexpr int D = kDimensionOf<std::decay_t<decltype(m)>>;
    const auto table = m.element_edge_table();
    return view<Index>(table.data(), m.is_p2() ? table.size() : 0, Simplex<D>::kEdges, self);
  });
}

// The columns a node list of `order` has for an entity of `corners` corners (a simplex of corners - 1
// dimensions: its corners, then one node per edge).
int columns(int corners, int order) { return order == 1 ? corners : corners + corners * (corners - 1) / 2; }

// The order a node list's width gives, or Error naming the argument.
int order_of(const IntArray& nodes, int corners, const std::string& what) {
  if (nodes.ndim() == 2 && nodes.shape(1) == columns(corners, 1)) return 1;
  if (nodes.ndim() == 2 && nodes.shape(1) == columns(corners, 2)) return 2;
  throw Error("Mesh: " + what + ": an array of " + std::to_string(columns(corners, 1)) + " (P1) or " + std::to_string(columns(corners, 2)) +
              " (P2) columns expected");
}

std::vector<int> refs_or_zeros(const std::optional<IntArray>& refs, std::size_t count, const std::string& what) {
  if (!refs) return std::vector<int>(count, 0);
  if (refs->ndim() != 1 || static_cast<std::size_t>(refs->shape(0)) != count)
    throw Error("Mesh: " + what + ": one ref per entity expected (" + std::to_string(count) + ")");
  return {refs->data(), refs->data() + count};
}

template <int D>
PyMesh assembled(const DoubleArray& points, const IntArray& elements, const std::optional<IntArray>& facets,
                 const std::optional<IntArray>& point_refs, const std::optional<IntArray>& element_refs,
                 const std::optional<IntArray>& facet_refs) {
  RawMesh<D> raw;
  const auto node_count = static_cast<std::size_t>(points.shape(0));
  raw.nodes.resize(node_count);
  std::copy_n(points.data(), node_count * D, &raw.nodes.front()[0]);
  raw.node_refs = refs_or_zeros(point_refs, node_count, "point_refs");
  raw.order = order_of(elements, D + 1, "elements");
  raw.element_nodes.assign(elements.data(), elements.data() + elements.size());
  raw.element_refs = refs_or_zeros(element_refs, static_cast<std::size_t>(elements.shape(0)), "element_refs");
  if (facets) {
    raw.facet_order = order_of(*facets, D, "facets");
    raw.facet_nodes.assign(facets->data(), facets->data() + facets->size());
    raw.facet_refs = refs_or_zeros(facet_refs, static_cast<std::size_t>(facets->shape(0)), "facet_refs");
  }
  raw.element_keyword = "elements";
  raw.facet_keyword = "facets";
  return assemble_mesh(std::move(raw), "Mesh");
}

PyMesh mesh_from_arrays(const DoubleArray& points, const IntArray& elements, const std::optional<IntArray>& facets,
                        const std::optional<IntArray>& point_refs, const std::optional<IntArray>& element_refs,
                        const std::optional<IntArray>& facet_refs) {
  if (points.ndim() != 2 || (points.shape(1) != 2 && points.shape(1) != 3))
    throw Error("Mesh: points: an array of shape (n, 2) or (n, 3) expected");
  if (points.shape(1) == 2) return assembled<2>(points, elements, facets, point_refs, element_refs, facet_refs);
  return assembled<3>(points, elements, facets, point_refs, element_refs, facet_refs);
}

std::string representation(const PyMesh& mesh) {
  return visit_mesh(mesh, [](const auto& m) {
    return "<hocav.Mesh " + std::to_string(kDimensionOf<std::decay_t<decltype(m)>>) + "D P" + std::to_string(m.order()) + ": " +
           std::to_string(m.vertex_count()) + " vertices, " + std::to_string(m.element_count()) + " elements, " +
           std::to_string(m.facet_count()) + " facets>";
  });
}

}  // namespace

void bind_mesh(py::module_& module) {
  py::class_<PyMesh>(module, "Mesh", R"(A triangle (2D) or tetrahedron (3D) mesh, P1 or P2.

Mesh(points, elements, facets=None, *, point_refs=None, element_refs=None, facet_refs=None)

points: (n, 2) or (n, 3) floats, every node (corners and, for P2, mid-edge nodes).
elements: (m, 3|6) in 2D, (m, 4|10) in 3D: 0-based node ids, corners then the P2 nodes of the
edges in VTK's (and meshio's) order.
facets: the boundary facets, (f, 2|3) in 2D, (f, 3|6) in 3D.
The mesh is checked as a file is (ids in range, consistent P2 nodes, facets on element faces): an
error raises hocav.Error. The arrays are copied once into the library's storage.

Its arrays (points, elements, facets, refs, and the P2 edges, edge_nodes and element_edges) are
read-only views of that storage: no copy. A Mesh never changes: adapt and curve return new ones.)")
      .def(py::init(&mesh_from_arrays), py::arg("points"), py::arg("elements"), py::arg("facets") = py::none(), py::kw_only(),
           py::arg("point_refs") = py::none(), py::arg("element_refs") = py::none(), py::arg("facet_refs") = py::none())
      .def_property_readonly(
          "dimension", [](const PyMesh& mesh) { return dimension_of(mesh.mesh); }, "2 or 3")
      .def_property_readonly(
          "order", [](const PyMesh& mesh) { return visit_mesh(mesh, [](const auto& m) { return m.order(); }); },
          "1 (straight) or 2 (P2 nodes on the edges)")
      .def_property_readonly("points", &points, "(vertices, dimension) float64 view: the element corners")
      .def_property_readonly("elements", &elements, "(elements, dimension + 1) int32 view: corner ids")
      .def_property_readonly("facets", &facets, "(facets, dimension) int32 view: boundary facets' corner ids")
      .def_property_readonly(
          "point_refs", [](const py::object& self) { return refs(self, [](const auto& m) { return m.vertex_refs(); }); },
          "(vertices,) int32 view")
      .def_property_readonly(
          "element_refs", [](const py::object& self) { return refs(self, [](const auto& m) { return m.element_refs(); }); },
          "(elements,) int32 view")
      .def_property_readonly(
          "facet_refs", [](const py::object& self) { return refs(self, [](const auto& m) { return m.facet_refs(); }); },
          "(facets,) int32 view")
      .def_property_readonly("edges", &edges, "P2: (edges, 2) int32 view, each edge's vertices (empty for P1)")
      .def_property_readonly("edge_nodes", &edge_nodes, "P2: (edges, dimension) float64 view, each edge's node")
      .def_property_readonly("element_edges", &element_edges, "P2: (elements, 3|6) int32 view, each element's edges in VTK's local order")
      .def("__repr__", &representation);
}

}  // namespace hocav::python
