// The generated cases behind `hocav generate`: each has a name, a one-line description, named real
// options with defaults, and a function making the mesh. A new case is one more entry in
// case_registry.cpp; the command line and its help follow from the entries.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "io/mesh_file.hpp"

namespace hocav {

struct CaseOption {
  std::string name;  // as on the command line without the dashes, e.g. "r-in"
  std::string description;
  double default_value = 0;
};

// Option values by option name.
using CaseValues = std::map<std::string, double>;

struct CaseDefinition {
  std::string name;
  std::string description;
  int dimension = 2;
  std::vector<CaseOption> options;
  // Called with a value for every option (defaults filled in).
  std::function<AnyMesh(const CaseValues&)> make;
  // Writes the CAD model of the case's domain (.brep, .step) for `hocav curve --surface cad:FILE`,
  // with the same values; empty for a case with no curved boundary.
  std::function<void(const CaseValues&, const std::string& path)> write_cad;
};

const std::vector<CaseDefinition>& case_definitions();

// Throws Error naming the known cases when there is no case of that name.
const CaseDefinition& find_case(const std::string& name);

// Generates a case; `values` may give any subset of its options (Error for an unknown one).
AnyMesh generate_case(const CaseDefinition& definition, const CaseValues& values = {});

}  // namespace hocav
