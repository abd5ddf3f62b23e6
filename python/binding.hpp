// What the two halves of the module share (docs/python.md): numpy arrays to and from the library's
// vectors, and a mesh as Python sees it. A thin layer: every computation is the library's.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "geom/sym_mat.hpp"
#include "io/mesh_file.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav::python {

namespace py = pybind11;

// Arrays given by Python: C-contiguous, converted to the type when needed (that is the one copy of a
// foreign dtype or layout; the library then copies the values into its own vectors).
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IntArray = py::array_t<int, py::array::c_style | py::array::forcecast>;

// A mesh with its nodes' places in the file it was read from (read_metric maps a .sol with them);
// a mesh made by the module numbers its nodes as every writer does (vertices, then P2 nodes).
using PyMesh = MeshFileContent;

// The D of a Mesh<D> (in generic lambdas over a PyMesh's variant).
template <class M>
constexpr int kDimensionOf = 0;
template <int D>
constexpr int kDimensionOf<Mesh<D>> = D;
PyMesh with_writer_numbering(AnyMesh mesh);

// Calls f(mesh) with the Mesh<D> a PyMesh holds (f returns one type for both).
template <class F>
auto visit_mesh(const PyMesh& mesh, F&& f) {
  return std::visit([&f](const auto& m) { return f(m); }, mesh.mesh);
}

// Metrics (one SymMat per row: the lower triangle row by row, the .sol order) as an (n, 3) or (n, 6)
// array that owns the vector it was moved from: no copy.
template <int D>
py::array_t<double> array_of_metrics(std::vector<SymMat<D>>&& metrics);
// And back, checking the shape: `rows` matrices expected. `what` names the argument in errors.
template <int D>
std::vector<SymMat<D>> metrics_of_array(const DoubleArray& array, Index rows, const std::string& what);

// The boundary geometry that a `surface` option ('p3', 'none', 'cad:FILE') names, as a function of
// the mesh whose boundary it follows, called without the GIL. Made with the GIL held: a CAD surface
// imports hocav._gmsh (python/cad_geometry.hpp).
template <int D>
using GeometryMaker = std::function<std::unique_ptr<BoundaryGeometry<D>>(const Mesh<D>&)>;
template <int D>
GeometryMaker<D> geometry_maker(const std::string& surface);

void bind_mesh(py::module_& module);
void bind_metrics(py::module_& module);
void bind_jobs(py::module_& module);

}  // namespace hocav::python
