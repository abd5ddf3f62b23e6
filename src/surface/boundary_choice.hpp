// Which geometry the boundary follows (`--surface` of `hocav curve` and `hocav adapt`,
// docs/surface.md): none (boundary nodes stay), the P3 surrogate of the mesh's own boundary, or a
// CAD model. Named by text only at the edges (command line, Python); the drivers take the geometry.
#pragma once

#include <memory>
#include <string>

#include "mesh/mesh.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

enum class BoundaryKind { kNone, kP3Surrogate, kCad };

struct BoundaryChoice {
  BoundaryKind kind = BoundaryKind::kP3Surrogate;
  std::string cad_path;  // kCad: a STEP or BREP file
};

// "none", "p3" or "cad:FILE"; throws Error for anything else.
BoundaryChoice boundary_choice_named(const std::string& name);

// Reads a CAD model (a STEP or BREP file) as the geometry of `mesh`'s boundary, the mesh's facet
// refs matched to its entities.
template <int D>
using CadBoundaryMaker = std::unique_ptr<BoundaryGeometry<D>> (*)(const std::string& cad_path, const Mesh<D>& mesh);

// The geometry of `choice` for `mesh`: nullptr for none, the P3 surrogate of its boundary, or the
// CAD model that `make_cad` reads (Error when it is null). The reader is a parameter because it
// calls gmsh, which the library does not link: the Python module imports it only for a CAD model.
template <int D>
std::unique_ptr<BoundaryGeometry<D>> make_boundary_geometry(const BoundaryChoice& choice, const Mesh<D>& mesh,
                                                            CadBoundaryMaker<D> make_cad);

// The CAD reader of hocav_gmsh (CadBoundary, through gmsh; cad_boundary_maker_gmsh.cpp, or the
// command's gmsh module, src/plugin/gmsh_services.hpp), and make_boundary_geometry with it.
template <int D>
std::unique_ptr<BoundaryGeometry<D>> make_cad_boundary(const std::string& cad_path, const Mesh<D>& mesh);
template <int D>
std::unique_ptr<BoundaryGeometry<D>> make_boundary_geometry(const BoundaryChoice& choice, const Mesh<D>& mesh);

}  // namespace hocav
