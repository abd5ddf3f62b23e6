// Metrics asked by global vertex id of the processes that hold them: each process holds a run of
// consecutive ids (rank 0 all of them, as a scatter from rank 0 has it, or the run of a metric file
// each process read, as a mesh read in pieces has it).
#pragma once

#include <span>
#include <vector>

#include "base/index.hpp"
#include "geom/sym_mat.hpp"

namespace hocav {

// Collective. This process holds the metrics of ids [held_first, held_first + held.size()); returns
// the metric of each of `ids`, each asked of the process whose run holds it (throws Error for an id
// that no run holds). `bytes_sent` grows by what this process sent to others.
template <int D>
std::vector<SymMat<D>> metrics_by_global_id(std::span<const Index> ids, Index held_first, const std::vector<SymMat<D>>& held,
                                            long long& bytes_sent);

}  // namespace hocav
