#include "surface/boundary_choice.hpp"

#include "base/error.hpp"

namespace hocav {

BoundaryChoice boundary_choice_named(const std::string& name) {
  if (name == "none") return {BoundaryKind::kNone, ""};
  if (name == "p3") return {BoundaryKind::kP3Surrogate, ""};
  if (name.starts_with("cad:") && name.size() > 4) return {BoundaryKind::kCad, name.substr(4)};
  throw Error("--surface: 'p3', 'cad:FILE' or 'none', not '" + name + "'");
}

}  // namespace hocav
