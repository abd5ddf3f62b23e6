// A solution file written by every process at once, each its run of the rows (docs/distributed.md
// §Reading in pieces): no process holds every row.
#pragma once

#include <string>

#include "io/solution_file.hpp"

namespace hocav {

// Every process at once: the .solb at `path` of `count` rows of `run`'s kind, process r's run of
// rows (`run`, the rows from `first_row` on) in its place; the file is the one write_solution_file
// writes of the whole. Rank 0 writes the keywords with a hole for the rows (the output's temporary
// in the command's OutputSet, renamed into place by its commit), then every process writes its rows
// there. Throws Error when the file cannot be written.
void write_solution_runs(const std::string& path, const SolutionField& run, Index first_row, Index count);

}  // namespace hocav
