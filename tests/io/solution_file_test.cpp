#include "io/solution_file.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "base/error.hpp"
#include "gamma_test_support.hpp"
#include "io/gamma_mesh.hpp"
#include "shared_data.hpp"

namespace hocav {
namespace {

using testing_support::error_of;
using testing_support::GammaBinaryBuilder;
using testing_support::read_file;
using testing_support::temporary_path;
using testing_support::write_file;

// Every kind of field, with values that need all 17 digits.
SolutionFileContent every_kind_of_field(int dimension, Index count) {
  SolutionFileContent content{dimension, count, {}};
  int seed = 0;
  for (SolutionKind kind : {SolutionKind::kScalar, SolutionKind::kSymmetricMatrix, SolutionKind::kVector, SolutionKind::kMatrix}) {
    SolutionField& field = content.fields.emplace_back(SolutionField{kind, dimension, {}});
    for (Index i = 0; i < count * field.components(); ++i) field.values.push_back(std::sin(0.7 * ++seed) * 1e3);
  }
  return content;
}

void expect_same_content(const SolutionFileContent& expected, const SolutionFileContent& actual, bool single_precision) {
  EXPECT_EQ(actual.dimension, expected.dimension);
  EXPECT_EQ(actual.count, expected.count);
  ASSERT_EQ(actual.fields.size(), expected.fields.size());
  for (std::size_t f = 0; f < expected.fields.size(); ++f) {
    EXPECT_EQ(actual.fields[f].kind, expected.fields[f].kind);
    EXPECT_EQ(actual.fields[f].count(), expected.count);
    ASSERT_EQ(actual.fields[f].values.size(), expected.fields[f].values.size());
    for (std::size_t i = 0; i < expected.fields[f].values.size(); ++i) {
      double wanted = expected.fields[f].values[i];
      if (single_precision) wanted = static_cast<float>(wanted);
      EXPECT_EQ(std::bit_cast<std::uint64_t>(actual.fields[f].values[i]), std::bit_cast<std::uint64_t>(wanted))
          << "field " << f << " value " << i;
    }
  }
}

TEST(SolutionFile, RoundTripsEveryKindOfField) {
  for (int dimension : {2, 3})
    for (int version = 0; version <= 4; ++version)
      for (const char* extension : {".sol", ".solb"}) {
        SCOPED_TRACE(std::string(extension) + " " + std::to_string(dimension) + "D version " + std::to_string(version));
        SolutionFileContent content = every_kind_of_field(dimension, 7);
        std::string path = temporary_path("fields" + std::to_string(version) + extension);
        write_solution_file(path, content, version);
        expect_same_content(content, read_solution_file(path), version == 1 && std::string(extension) == ".solb");
      }
}

// The runs of a file's rows (what each process of a distributed run reads) put end to end are the
// file's rows, each run's content counting the file's rows.
TEST(SolutionFile, RunsOfRowsPutEndToEndAreTheFile) {
  for (const char* extension : {".sol", ".solb"}) {
    const SolutionFileContent whole = every_kind_of_field(3, 10);
    const std::string path = temporary_path(std::string("runs") + extension);
    write_solution_file(path, whole);
    for (int count : {1, 2, 3, 4, 11}) {
      SolutionFileContent joined{3, whole.count, {}};
      for (const SolutionField& field : whole.fields) joined.fields.push_back({field.kind, 3, {}});
      for (int index = 0; index < count; ++index) {
        const SolutionFileContent run = read_solution_file_run(path, {index, count});
        EXPECT_EQ(run.count, whole.count);
        ASSERT_EQ(run.fields.size(), whole.fields.size());
        for (std::size_t f = 0; f < whole.fields.size(); ++f) {
          EXPECT_EQ(run.fields[f].count(), slice_start(whole.count, index + 1, count) - slice_start(whole.count, index, count));
          joined.fields[f].values.insert(joined.fields[f].values.end(), run.fields[f].values.begin(), run.fields[f].values.end());
        }
      }
      SCOPED_TRACE(std::string(extension) + " in " + std::to_string(count) + " runs");
      expect_same_content(whole, joined, false);
    }
  }
}

// The skeleton's hole, filled row by row at its layout's offsets, makes the file write_solution_file
// writes of the whole (what the processes of a distributed run do, each its rows).
TEST(SolutionFile, ASkeletonFilledInPlaceIsTheWholeFile) {
  for (int dimension : {2, 3}) {
    const int components = dimension * (dimension + 1) / 2;
    SolutionField rows{SolutionKind::kSymmetricMatrix, dimension, {}};
    for (int i = 0; i < 7 * components; ++i) rows.values.push_back(1.0 / (i + 3));
    const std::string whole = temporary_path("whole.solb"), skeleton = temporary_path("skeleton.solb");
    write_solution_file(whole, {dimension, 7, {rows}});
    const SolutionRowsLayout layout = write_solution_skeleton(skeleton, dimension, 7, {SolutionKind::kSymmetricMatrix});
    EXPECT_EQ(layout.row_bytes, static_cast<std::uint64_t>(components) * sizeof(double));
    std::string bytes = read_file(skeleton);
    ASSERT_EQ(bytes.size(), read_file(whole).size());
    std::memcpy(bytes.data() + layout.first_row_offset, rows.values.data(), rows.values.size() * sizeof(double));
    EXPECT_EQ(bytes, read_file(whole)) << dimension << "D";
  }
}

TEST(SolutionFile, KeepsTheTypeHeader32BitInVersion4) {
  // Header 8, Dimension 4+8+4, SolAtVertices 4+8 + count 8 + types 4 * (1 + 2), rows 5 * (1 + 3) * 8, End 4+8.
  SolutionFileContent content{2, 5, {}};
  content.fields.push_back({SolutionKind::kScalar, 2, std::vector<double>(5, 1.0)});
  content.fields.push_back({SolutionKind::kSymmetricMatrix, 2, std::vector<double>(15, 2.0)});
  std::string path = temporary_path("v4.solb");
  write_solution_file(path, content, 4);
  EXPECT_EQ(read_file(path).size(), 8u + 16 + 20 + 12 + 160 + 12);
}

TEST(SolutionFile, WritesAsciiAsLibMeshbDoes) {
  SolutionFileContent content{2, 2, {}};
  content.fields.push_back({SolutionKind::kSymmetricMatrix, 2, {1, 0.5, 2, 3, 0, 0.1}});
  std::string path = temporary_path("layout.sol");
  write_solution_file(path, content);
  EXPECT_EQ(read_file(path), "MeshVersionFormatted 2\n\nDimension 2\n\nSolAtVertices\n2\n1 3\n1 0.5 2\n3 0 0.1\n\nEnd\n");
}

TEST(SolutionFile, ReadsByteSwappedBinary) {
  GammaBinaryBuilder file(2, true);
  file.dimension(3);
  file.begin_keyword(62);
  file.count(1);
  file.int32(1);
  file.int32(3);
  for (double value : {1.0, 0.0, 2.0, 0.0, 0.0, 3.0}) file.real(value);
  file.end_keyword();
  file.end();
  SolutionFileContent content = read_solution_file(write_file("swapped.solb", file.bytes()));
  ASSERT_EQ(content.fields.size(), 1u);
  EXPECT_EQ(content.fields[0].values, (std::vector<double>{1, 0, 2, 0, 0, 3}));
  EXPECT_NO_THROW(checked_metric_field(content, "swapped.solb", 3, 1));
}

// ---- the third-party metrics ----

void expect_metric_of_mesh(const std::string& mesh_path, const std::string& sol_path, Index count, double first_m11) {
  ::testing::internal::CaptureStderr();
  MeshFileContent mesh = read_gamma_mesh(mesh_path);
  ::testing::internal::GetCapturedStderr();
  SolutionFileContent content = read_solution_file(sol_path);
  EXPECT_EQ(content.count, count);
  const SolutionField& metric = checked_metric_field(content, sol_path, 3, mesh.file_node_count);
  EXPECT_EQ(metric.count(), count);
  EXPECT_EQ(metric.values[0], first_m11);
}

TEST(SolutionFile, ReadsTheThirdPartyMetricsAsPositiveDefinite) {
  using testing_support::shared_data_path;
  const std::string torus = shared_data_path("mmg-torus/torus.mesh"), linear = shared_data_path("ugawg-linear/linear.mesh");
  if (auto missing = testing_support::missing_shared_data({torus, linear}); !missing.empty()) GTEST_SKIP() << missing;
  expect_metric_of_mesh(torus, shared_data_path("mmg-torus/torus-met.sol"), 4351, 32.5918);
  expect_metric_of_mesh(linear, shared_data_path("ugawg-linear/linear.sol"), 9476, 99.999999999999986);
}

// ---- checks of a metric against its mesh ----

SolutionFileContent metric_field(int dimension, std::vector<double> values) {
  SolutionFileContent content{dimension, 0, {}};
  content.fields.push_back({SolutionKind::kSymmetricMatrix, dimension, std::move(values)});
  content.count = content.fields[0].count();
  return content;
}

TEST(SolutionFile, ChecksMetricsAgainstTheirMesh) {
  // 2D: [[1, 2], [2, 1]] has a positive diagonal but is indefinite.
  SolutionFileContent indefinite = metric_field(2, {1, 0, 1, /**/ 1, 2, 1});
  EXPECT_EQ(error_of([&] { checked_metric_field(indefinite, "m.sol", 2, 2); }),
            "m.sol: SolAtVertices: metric at vertex 2 is not positive definite");
  // 3D, order m11 m12 m22 m13 m23 m33: leading minors 1 and 1 but a negative determinant.
  SolutionFileContent negative_determinant = metric_field(3, {1, 0, 1, 0.9, 0.9, 1});
  EXPECT_EQ(error_of([&] { checked_metric_field(negative_determinant, "m.sol", 3, 1); }),
            "m.sol: SolAtVertices: metric at vertex 1 is not positive definite");
  // The same off-diagonal terms with a larger m33 are fine.
  SolutionFileContent definite = metric_field(3, {1, 0, 1, 0.9, 0.9, 2});
  EXPECT_EQ(&checked_metric_field(definite, "m.sol", 3, 1), &definite.fields[0]);
  // diag(1, 0.01, 1) on disk; read as the upper triangle row by row it would have m22 = 0.
  SolutionFileContent small_m22 = metric_field(3, {1, 0, 0.01, 0, 0, 1});
  EXPECT_NO_THROW(checked_metric_field(small_m22, "m.sol", 3, 1));

  SolutionFileContent not_finite = metric_field(2, {1, 0, 1, 1, 0, std::numeric_limits<double>::quiet_NaN()});
  EXPECT_EQ(error_of([&] { checked_metric_field(not_finite, "m.sol", 2, 2); }), "m.sol: SolAtVertices: metric at vertex 2 is not finite");
  std::string counts = error_of([&] { checked_metric_field(definite, "m.sol", 3, 7); });
  EXPECT_EQ(counts.rfind("m.sol: SolAtVertices: ", 0), 0u) << counts;
  EXPECT_NE(counts.find(" 1 "), std::string::npos) << counts;
  EXPECT_NE(counts.find(" 7 "), std::string::npos) << counts;
  EXPECT_EQ(error_of([&] { checked_metric_field(definite, "m.sol", 2, 1); }), "m.sol: Dimension: the solution is 3D but the mesh is 2D");

  // A run's rows (read_solution_file_run): named by their file row; the file's count is checked.
  SolutionFileContent run_of_file = metric_field(2, {1, 0, 1, 1, 2, 1});
  run_of_file.count = 9;
  EXPECT_EQ(error_of([&] { checked_metric_field(run_of_file, "m.sol", 2, 9, 5); }),
            "m.sol: SolAtVertices: metric at vertex 7 is not positive definite");
  EXPECT_NE(error_of([&] { checked_metric_field(run_of_file, "m.sol", 2, 2, 5); }).find(" 9 "), std::string::npos);

  SolutionFileContent scalar_first = every_kind_of_field(2, 3);
  scalar_first.fields.erase(scalar_first.fields.begin() + 1);  // no symmetric matrix left
  EXPECT_NE(error_of([&] { checked_metric_field(scalar_first, "m.sol", 2, 3); }).find("no symmetric-matrix field"), std::string::npos);
}

// mmg's isotropic size field (type 1): each size h is the metric I/h², in the on-disk order.
TEST(SolutionFile, ReadsAnIsotropicSizeFieldAsAMetric) {
  SolutionFileContent sizes{3, 2, {{SolutionKind::kScalar, 3, {0.5, 0.1}}}};
  add_metric_of_sizes(sizes, "h.sol");
  ASSERT_EQ(sizes.fields.size(), 2u);
  const SolutionField& metric = checked_metric_field(sizes, "h.sol", 3, 2);
  EXPECT_EQ(metric.values, (std::vector<double>{4, 0, 4, 0, 0, 4, /**/ 1 / (0.1 * 0.1), 0, 1 / (0.1 * 0.1), 0, 0, 1 / (0.1 * 0.1)}));
  SolutionFileContent sizes_2d{2, 1, {{SolutionKind::kScalar, 2, {0.25}}}};
  add_metric_of_sizes(sizes_2d, "h.sol");
  EXPECT_EQ(checked_metric_field(sizes_2d, "h.sol", 2, 1).values, (std::vector<double>{16, 0, 16}));

  // A symmetric-matrix field wins over the sizes: nothing is added.
  SolutionFileContent both = every_kind_of_field(3, 2);
  add_metric_of_sizes(both, "h.sol");
  EXPECT_EQ(both.fields.size(), 4u);

  SolutionFileContent zero{2, 3, {{SolutionKind::kScalar, 2, {0.1, 0.2, 0}}}};
  EXPECT_EQ(error_of([&] { add_metric_of_sizes(zero, "h.sol"); }), "h.sol: SolAtVertices: size at vertex 3 is not positive");
  EXPECT_EQ(error_of([&] { add_metric_of_sizes(zero, "h.sol", 40); }), "h.sol: SolAtVertices: size at vertex 43 is not positive");
  SolutionFileContent infinite{2, 1, {{SolutionKind::kScalar, 2, {std::numeric_limits<double>::infinity()}}}};
  EXPECT_EQ(error_of([&] { add_metric_of_sizes(infinite, "h.sol"); }), "h.sol: SolAtVertices: size at vertex 1 is not finite");
}

TEST(SolutionFile, PicksTheFirstSymmetricMatrixField) {
  SolutionFileContent content{2, 1, {}};
  content.fields.push_back({SolutionKind::kScalar, 2, {5}});
  content.fields.push_back({SolutionKind::kSymmetricMatrix, 2, {1, 0, 1}});
  content.fields.push_back({SolutionKind::kSymmetricMatrix, 2, {4, 0, 4}});
  EXPECT_EQ(&checked_metric_field(content, "m.sol", 2, 1), &content.fields[1]);
}

// ---- malformed input ----

void expect_solution_read_error(const std::string& name, const std::string& bytes, std::initializer_list<std::string> parts) {
  std::string path = write_file(name, bytes);
  ::testing::internal::CaptureStderr();
  std::string message = error_of([&] { read_solution_file(path); });
  ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

TEST(SolutionFile, RefusesMalformedFiles) {
  const std::string header = "MeshVersionFormatted 2\nDimension 2\n";
  expect_solution_read_error("missing.sol", header + "Time\n0.5\n", {"SolAtVertices: missing"});
  expect_solution_read_error("no_dimension.sol", "SolAtVertices\n1\n1 1\n2\n", {"SolAtVertices: ", "no Dimension"});
  expect_solution_read_error("type.sol", header + "SolAtVertices\n1\n1 7\n2\n", {"SolAtVertices: ", "unknown solution type 7"});
  expect_solution_read_error("fields.sol", header + "SolAtVertices\n1\n0\n", {"SolAtVertices: ", "field count 0"});
  expect_solution_read_error("truncated.sol", header + "SolAtVertices\n2\n1 3\n1 0 1\n1 0\n", {"SolAtVertices: ", "end of file"});
  expect_solution_read_error("twice.sol", header + "SolAtVertices\n1\n1 1\n2\nSolAtVertices\n1\n1 1\n2\n", {"appears twice"});
  expect_solution_read_error("negative.sol", header + "SolAtVertices\n-1\n1 1\n", {"SolAtVertices: ", "negative count"});

  GammaBinaryBuilder truncated(3);
  truncated.dimension(2);
  truncated.begin_keyword(62);
  truncated.count(3);
  truncated.int32(1);
  truncated.int32(1);
  truncated.real(1.0);
  expect_solution_read_error("truncated.solb", truncated.bytes(), {"SolAtVertices: truncated file, entity 2"});
  GammaBinaryBuilder infinite(2);
  infinite.dimension(2);
  infinite.begin_keyword(62);
  infinite.count(2);
  infinite.int32(1);
  infinite.int32(1);
  infinite.real(1.0);
  infinite.real(std::numeric_limits<double>::infinity());
  infinite.end_keyword();
  infinite.end();
  expect_solution_read_error("infinite.solb", infinite.bytes(), {"SolAtVertices: ", "not finite", "entity 2"});
}

TEST(SolutionFile, RefusesToWriteInconsistentContent) {
  SolutionFileContent content = every_kind_of_field(3, 4);
  EXPECT_THROW(write_solution_file(temporary_path("x.txt"), content), Error);
  content.fields[1].values.pop_back();
  EXPECT_THROW(write_solution_file(temporary_path("short.sol"), content), Error);
  EXPECT_THROW(write_solution_file(temporary_path("missing/dir.solb"), every_kind_of_field(3, 4)), Error);
}

}  // namespace
}  // namespace hocav
