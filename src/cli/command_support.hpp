// What the commands share: their warnings, the input mesh's check, the progress line of a
// curving run and the line of a distributed curving's round. The rest they share is the library's, which each command includes itself
// (io/node_metrics.hpp, report/curved_vtu.hpp, report/mesh_summary.hpp, surface/boundary_choice.hpp).
#pragma once

#include <iostream>
#include <memory>
#include <string>

#include "adapt/curving_run.hpp"
#include "cli/progress_line.hpp"
#include "mesh/input_check.hpp"
#include "parallel/distributed_curving.hpp"

namespace hocav {

// A warning of the commands on stderr: one line, "hocav: warning: " and what it says.
inline void warn_on_stderr(const std::string& warning) { std::cerr << "hocav: warning: " << warning << '\n'; }

// check_input_mesh, its defects (which the operators work around) as a warning on stderr.
template <int D>
void check_mesh_or_warn(const Mesh<D>& mesh, const std::string& path) {
  if (const std::string defects = check_input_mesh(mesh, path); !defects.empty()) warn_on_stderr(defects);
}

// The progress line of a curving of a mesh on stderr: drawn when wanted, stderr is a terminal and the
// mesh is large enough to wait for.
class CurvingProgress {
 public:
  template <int D>
  CurvingProgress(const Mesh<D>& mesh, int passes, bool wanted);
  // Makes `options` redraw the line (when there is one).
  void attach(CurvingOptions& options);
  // Shows the whole work done: the last few vertices are not reported.
  void complete();

 private:
  double total_ = 0;
  std::unique_ptr<ProgressLine> line_;
};

// A round of a distributed curving (docs/distributed.md §Curving) on stderr.
void print_curving_round(const DistributedCurvingRound& figures);

}  // namespace hocav
