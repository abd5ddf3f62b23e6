// What the module hocav._gmsh gives hocav._hocav (docs/python.md, "gmsh"): the library's CAD reader
// make_cad_boundary, which reads models through gmsh. Only _gmsh links gmsh, so that `import hocav`
// loads none of its libraries; _hocav imports _gmsh on the first CAD surface and takes these
// function pointers from its capsule, for the library's make_boundary_geometry. Both modules are
// built from the same headers, so the objects the pointers make and take have one layout on both sides.
#pragma once

#include "surface/boundary_choice.hpp"

namespace hocav::python {

struct CadGeometryMakers {
  CadBoundaryMaker<2> two;
  CadBoundaryMaker<3> three;

  template <int D>
  CadBoundaryMaker<D> of() const {
    if constexpr (D == 2)
      return two;
    else
      return three;
  }
};

// The capsule's name, checked when _hocav takes the pointer out.
inline constexpr const char* kCadGeometryMakersName = "hocav._gmsh.cad_geometry_makers";

}  // namespace hocav::python
