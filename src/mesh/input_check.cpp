#include "mesh/input_check.hpp"

#include "base/error.hpp"
#include "mesh/consistency.hpp"
#include "mesh/mesh_defects.hpp"

namespace hocav {

template <int D>
std::string check_input_mesh(const Mesh<D>& mesh, const std::string& path) {
  ConsistencyOptions consistency;
  consistency.require_positive_orientation = !mesh.is_p2();  // as stats: a valid curved element may be an inverted P1 one
  if (auto problems = check_consistency(mesh, consistency); !problems.empty())
    throw Error(path + ": inconsistent mesh: " + std::to_string(problems.size()) + (problems.size() == 1 ? " problem" : " problems") +
                " (first: " + problems.front() + "; see hocav stats)");
  const MeshDefects defects = find_mesh_defects(mesh);
  return defects.none() ? "" : path + ": " + defects.summary();
}

template std::string check_input_mesh(const Mesh<2>&, const std::string&);
template std::string check_input_mesh(const Mesh<3>&, const std::string&);

}  // namespace hocav
