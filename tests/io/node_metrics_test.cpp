#include "io/node_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gamma_test_support.hpp"
#include "io/record_run.hpp"

namespace hocav {
namespace {

using testing_support::error_of;
using testing_support::temporary_path;

// A scalar field's runs (what each process of a run from pieces reads of a --hessian field) put end
// to end are the field, the scalar found behind another field; a bad value is named by its file node.
TEST(NodeMetrics, ScalarRunsPutEndToEndAreTheField) {
  const Index count = 10;
  SolutionFileContent content{3, count, {{SolutionKind::kSymmetricMatrix, 3, {}}, {SolutionKind::kScalar, 3, {}}}};
  for (Index i = 0; i < count; ++i) {
    for (int c = 0; c < 6; ++c) content.fields[0].values.push_back(c % 2 == 0 ? 1.0 : 0.0);
    content.fields[1].values.push_back(std::sin(0.3 * static_cast<double>(i)));
  }
  const std::string path = temporary_path("scalar_runs.solb");
  write_solution_file(path, content);
  for (int runs : {1, 3, 4}) {
    std::vector<double> joined;
    for (int index = 0; index < runs; ++index) {
      const std::vector<double> run = read_scalar_run(path, 3, count, {index, runs});
      EXPECT_EQ(static_cast<Index>(run.size()), slice_start(count, index + 1, runs) - slice_start(count, index, runs));
      joined.insert(joined.end(), run.begin(), run.end());
    }
    EXPECT_EQ(joined, content.fields[1].values) << runs << " runs";
  }
  EXPECT_EQ(error_of([&] { read_scalar_run(path, 2, count, {}); }), path + ": Dimension: the solution is 3D but the mesh is 2D");
  EXPECT_EQ(error_of([&] { read_scalar_run(path, 3, count + 1, {}); }), path + ": SolAtVertices: 10 values for a mesh of 11 nodes");
  content.fields[1].values[7] = std::numeric_limits<double>::quiet_NaN();
  write_solution_file(path, content);
  const std::string not_finite = error_of([&] { read_scalar_run(path, 3, count, {1, 2}); });
  EXPECT_EQ(not_finite.rfind(path + ": SolAtVertices: ", 0), 0u) << not_finite;
  EXPECT_NE(not_finite.find("not finite"), std::string::npos) << not_finite;
  EXPECT_NE(not_finite.find('8'), std::string::npos) << not_finite;
  EXPECT_NO_THROW(read_scalar_run(path, 3, count, {0, 2}));  // rows 1-5 only
  content.fields.erase(content.fields.begin() + 1);
  write_solution_file(path, content);
  EXPECT_EQ(error_of([&] { read_scalar_run(path, 3, count, {}); }), path + ": SolAtVertices: no scalar field (type 1)");
}

}  // namespace
}  // namespace hocav
