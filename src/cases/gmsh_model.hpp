// The bridge to gmsh (4.8 C++ API) for the generated cases: a session guard for gmsh's global
// state and the extraction of its simplicial mesh into a Mesh<D>.
#pragma once

#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "base/error.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// Whether this build has gmsh (the CMake option HOCAV_WITH_GMSH). Without it the entry points that
// need gmsh (a GmshSession, the gmsh-meshed shells, CAD models) throw Error saying so
// (src/cases/gmsh_cases_without_gmsh.cpp, src/surface/cad_boundary_without_gmsh.cpp).
bool gmsh_available();

// Holds gmsh for the lifetime of one generation: gmsh keeps one global model, so sessions are
// serialized by a process-wide mutex (every use of the gmsh API in hocav goes through one); a
// second session in the thread that holds one is an Error rather than a deadlock. Reads no user
// configuration file and fixes the options that decide the result (one thread, fixed seed), so
// that the same inputs give the same mesh. Messages are silenced; gmsh's errors come back as
// Error. Restores the C locale gmsh changes.
class GmshSession {
 public:
  explicit GmshSession(const std::string& model_name);
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  std::unique_lock<std::mutex> lock_;
  std::string saved_locale_;
};

// Runs a call into gmsh, turning what gmsh throws (a std::string in 4.8) into Error("gmsh: ...").
template <class Call>
decltype(auto) call_gmsh(Call&& call) {
  try {
    return std::forward<Call>(call)();
  } catch (const std::string& message) {
    throw Error("gmsh: " + message);
  }
}

// A boundary entity of the gmsh model (dimension D - 1) and the ref its facets get.
struct GmshBoundaryEntity {
  int tag = 0;
  int ref = 0;
};

// The current gmsh model's mesh as a Mesh<D>: its vertices are the nodes used by its elements
// (triangles in 2D, where z must be 0; tetrahedra in 3D), in gmsh node-tag order; elements are
// oriented positively; every boundary face of the element mesh becomes a facet oriented outward,
// with the ref of the listed boundary entity that holds it (Error when none does). Topology built.
template <int D>
Mesh<D> extract_gmsh_mesh(const std::vector<GmshBoundaryEntity>& boundary, int element_ref);

}  // namespace hocav
