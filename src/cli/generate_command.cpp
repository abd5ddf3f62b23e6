// hocav generate CASE [case options] -o OUT [--order 1|2] [--cad-out CAD]: one subcommand per
// entry of the case registry, its options and help taken from the entry.
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "cases/case_registry.hpp"
#include "cases/concentric_shell.hpp"
#include "cli/command_support.hpp"
#include "cli/commands.hpp"
#include "cli/number_checks.hpp"
#include "io/output_set.hpp"
#include "report/mesh_summary.hpp"

namespace hocav {
namespace {

struct GenerateOptions {
  std::string output;
  int order = 1;
  std::string cad_output;
};

std::string format_default(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// "  annulus       --r-in 0.5  --r-out 1  --h 0.1" for every case, for the help of `generate`.
std::string generate_cases_footer() {
  std::ostringstream footer;
  footer << "Cases and their options (defaults), see `hocav generate CASE --help`:\n";
  for (const CaseDefinition& definition : case_definitions()) {
    footer << "  " << std::left << std::setw(24) << definition.name;
    for (const CaseOption& option : definition.options) footer << "  --" << option.name << ' ' << format_default(option.default_value);
    footer << '\n';
  }
  return footer.str();
}

void run_generate(const CaseDefinition& definition, const CaseValues& values, const GenerateOptions& options) {
  OutputSet outputs;
  check_writable_mesh_format(options.output);
  outputs.add_output(options.output, "-o");
  if (!options.cad_output.empty()) {
    if (!definition.write_cad) throw Error("--cad-out: case " + definition.name + " has no CAD model (its boundary is not curved)");
    check_cad_path(options.cad_output);
    outputs.add_output(options.cad_output, "--cad-out");
  }
  AnyMesh mesh = generate_case(definition, values);
  std::visit(
      [&options](auto& m) {
        if (options.order == 2) m.make_p2();
        write_mesh_file(options.output, m);
      },
      mesh);
  if (!options.cad_output.empty()) definition.write_cad(values, outputs.temporary_for(options.cad_output));
  outputs.commit();
  std::visit([&options](auto& m) { std::cout << "wrote " << options.output << ": " << mesh_summary(m) << '\n'; }, mesh);
  if (!options.cad_output.empty())
    std::cout << "wrote " << options.cad_output << ": the CAD model (for curve --surface cad:" << options.cad_output << ")\n";
}

}  // namespace

void add_generate_command(CLI::App& app) {
  auto options = std::make_shared<GenerateOptions>();
  CLI::App* command = app.add_subcommand("generate", "Generate the mesh of a test case (no input needed)");
  command->add_option("-o,--output", options->output, "mesh to write; the format follows the extension (.mesh, .meshb, .msh, .vtu)")
      ->required();
  command->add_option("--order", options->order, "element order: 2 adds straight P2 nodes")
      ->check(CLI::IsMember({1, 2}))
      ->capture_default_str();
  command->add_option("--cad-out", options->cad_output,
                      "also write the CAD model of the case's curved boundary (.brep, .step) for curve --surface cad:FILE");
  command->require_subcommand(1);
  command->footer(generate_cases_footer());
  for (const CaseDefinition& definition : case_definitions()) {
    auto values = std::make_shared<CaseValues>();
    CLI::App* case_command = command->add_subcommand(definition.name,
                                                     definition.description + " (" + std::to_string(definition.dimension) + "D)");
    case_command->fallthrough();  // -o and --order may follow the case name
    for (const CaseOption& option : definition.options) {
      (*values)[option.name] = option.default_value;
      case_command->add_option("--" + option.name, (*values)[option.name], option.description)
          ->check(finite_number())
          ->capture_default_str();
    }
    case_command->callback([&definition, values, options] { run_generate(definition, *values, *options); });
  }
}

}  // namespace hocav
