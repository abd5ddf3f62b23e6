// CadBoundary in a build without gmsh (CMake option HOCAV_WITH_GMSH=OFF): constructing one opens a
// GmshSession, which throws Error saying that the CAD model needs gmsh; no object ever exists, so
// the queries are never called.
#include "surface/cad_boundary_gmsh.hpp"

namespace hocav {
namespace {

[[noreturn]] void unreachable_without_gmsh() { throw Error("CadBoundary: no CAD model without gmsh"); }

}  // namespace

template <int D>
CadBoundary<D>::CadBoundary(const std::string& path) : session_(path + ": the CAD model") {}

template <int D>
CadBoundary<D>::CadBoundary(const std::string& path, const Mesh<D>&) : CadBoundary(path) {}

template <int D>
int CadBoundary<D>::entity_of_ref(int) const {
  unreachable_without_gmsh();
}

template <int D>
BoundaryPoint<D> CadBoundary<D>::closest_unlocked(const Vec<D>&, const ProjectionQuery&) const {
  unreachable_without_gmsh();
}

template <int D>
BoundaryPoint<D> CadBoundary<D>::project(const Vec<D>&, const ProjectionQuery&) const {
  unreachable_without_gmsh();
}

template <int D>
Vec<D> CadBoundary<D>::normal(const Vec<D>&, const ProjectionQuery&) const {
  unreachable_without_gmsh();
}

template <int D>
Vec<D> CadBoundary<D>::project_on_intersection(const Vec<D>&, int, int) const {
  unreachable_without_gmsh();
}

template class CadBoundary<2>;
template class CadBoundary<3>;

}  // namespace hocav
