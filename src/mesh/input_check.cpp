#include "mesh/input_check.hpp"

#include "base/error.hpp"
#include "mesh/consistency.hpp"
#include "mesh/inverted_input.hpp"
#include "mesh/mesh_defects.hpp"
#include "mesh/open_boundary.hpp"

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

template <int D>
void prepare_input_mesh(Mesh<D>& mesh, const std::string& path, const std::function<void(const std::string&)>& warn) {
  for (const std::string& said : {reorient_inverted_mesh(mesh, path), close_open_boundary(mesh, path)})
    if (!said.empty() && warn) warn(said);
}

template void prepare_input_mesh(Mesh<2>&, const std::string&, const std::function<void(const std::string&)>&);
template void prepare_input_mesh(Mesh<3>&, const std::string&, const std::function<void(const std::string&)>&);
template std::string check_input_mesh(const Mesh<2>&, const std::string&);
template std::string check_input_mesh(const Mesh<3>&, const std::string&);

}  // namespace hocav
