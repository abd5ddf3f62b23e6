// The module hocav._gmsh: the part of hocav that links gmsh (python/cad_geometry.hpp), imported by
// hocav._hocav on the first CAD surface only.
#include <pybind11/pybind11.h>

#include "cad_geometry.hpp"

PYBIND11_MODULE(_gmsh, module) {
  namespace py = pybind11;
  using hocav::make_cad_boundary;
  static const hocav::python::CadGeometryMakers makers{&make_cad_boundary<2>, &make_cad_boundary<3>};
  module.doc() = "hocav's CAD boundaries, read through gmsh (imported when a surface names a CAD model)";
  module.attr("cad_geometry_makers") = py::capsule(&makers, hocav::python::kCadGeometryMakersName);
}
