// Gamma solution files .sol (ASCII) / .solb (binary): SolAtVertices fields, one row per file node.
// Symmetric matrices are kept in the on-disk order m11 m12 m22 (2D) and m11 m12 m22 m13 m23 m33
// (3D), i.e. the lower triangle row by row; the metric module converts to its own type.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/index.hpp"
#include "io/record_run.hpp"

namespace hocav {

enum class SolutionKind { kScalar = 1, kVector = 2, kSymmetricMatrix = 3, kMatrix = 4 };

struct SolutionField {
  SolutionKind kind = SolutionKind::kScalar;
  int dimension = 3;
  std::vector<double> values;  // count() rows of components() values

  int components() const;
  Index count() const;
};

struct SolutionFileContent {
  int dimension = 3;
  Index count = 0;  // the number of rows (file nodes)
  std::vector<SolutionField> fields;

  // The first field of this kind (a matrix one of the content's dimension), or null.
  const SolutionField* first_of_kind(SolutionKind kind) const;
};

// Reads a .sol/.solb file. Throws Error naming file, keyword and line/entity on malformed input.
SolutionFileContent read_solution_file(const std::string& path);

// The rows of `run` only (a run of the file's rows, cut as a mesh file's entities are; a .solb is
// positioned past the others, a .sol read through): the content's count stays the file's; its
// fields hold rows run.of(count).first onwards.
SolutionFileContent read_solution_file_run(const std::string& path, const RecordRun& run);

// Writes a .sol/.solb file (all fields must have the same count); temporary name, then rename.
// Binary version: 0 picks 3 (4 when counts need 64 bits).
void write_solution_file(const std::string& path, const SolutionFileContent& content, int gamma_version = 0);

// Where the rows of a binary solution file lie, for writers that fill them in place.
struct SolutionRowsLayout {
  std::uint64_t first_row_offset = 0;  // the byte of the first row
  std::uint64_t row_bytes = 0;
};

// Writes the .solb at `path` (as write_solution_file does, through AtomicOutput) with fields of
// `kinds` and `count` rows, but leaves the rows unwritten: a hole other writers fill in place.
SolutionRowsLayout write_solution_skeleton(const std::string& path, int dimension, Index count, const std::vector<SolutionKind>& kinds);

// mmg's isotropic size field: when `content` holds no symmetric-matrix field of its dimension but a
// scalar one (SolAtVertices type 1, a size h per node), appends the metric I/h² of each size as a
// symmetric-matrix field. Throws Error "<file>: SolAtVertices: size at vertex N is not positive"
// (or not finite). The fields' first row is file row `first_row` (a run's).
void add_metric_of_sizes(SolutionFileContent& content, const std::string& path, Index first_row = 0);

// Checks a metric field against the mesh it goes with: a symmetric-matrix field of the mesh's
// dimension, one row per file node, every matrix finite and positive definite. Throws Error
// "<file>: SolAtVertices: <what> at vertex N" otherwise. Returns the field. For a run's content
// (read_solution_file_run), the file's count is checked and the rows are file rows from `first_row`.
const SolutionField& checked_metric_field(const SolutionFileContent& content, const std::string& path, int dimension, Index file_node_count,
                                          Index first_row = 0);

}  // namespace hocav
