// The cases `hocav bench` runs: a built-in mesh (`hocav generate`) sized to a target element count,
// the metric it is curved in, and the boundary curvature. A new case is one entry in bench_cases.cpp.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "cases/case_registry.hpp"
#include "geom/sym_mat.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// Where the metric comes from (docs/metrics.md): an analytic shear layer, the boundary sizes
// carried into the volume by gradation, or the mesh's own (implied) metric.
enum class BenchMetric { kShear, kSurfaceGraded, kImplied };

struct BenchCase {
  std::string name;       // as given to --cases
  std::string generator;  // the `hocav generate` case
  // The generator's options that give about `target` elements.
  std::function<CaseValues(double target)> options_for_target;
  BenchMetric metric;
  std::string surface;    // boundary curvature, as `hocav curve --surface`
  double largest_target;  // sizes above are skipped (the generator would take too long)
  std::string description;
};

const std::vector<BenchCase>& bench_cases();

// Throws Error naming the known cases when there is no case of that name.
const BenchCase& find_bench_case(const std::string& name);

// The metric of the case on its generated mesh, one matrix per vertex.
template <int D>
std::vector<SymMat<D>> bench_metric(BenchMetric metric, const Mesh<D>& mesh);

}  // namespace hocav
