// Gamma solution files: SolAtVertices through the shared keyword readers and writers.
#include "io/solution_file.hpp"

#include <cmath>
#include <utility>

#include "base/error.hpp"
#include "io/gamma_keyword_reader.hpp"
#include "io/gamma_keyword_writer.hpp"
#include "io/gamma_keywords.hpp"
#include "io/gamma_mesh.hpp"
#include "io/mesh_file.hpp"

namespace hocav {
namespace {

constexpr int kMaxFields = 1000;  // libMeshb's limit on the types of one keyword

// Rows [first, last) of the file's are kept (all of them by default); content.count is the file's.
template <class Reader>
void read_sol_at_vertices(Reader& reader, SolutionFileContent& content, const RecordRun& run) {
  if (reader.dimension() == 0) reader.fail("no Dimension before the solution");
  content.dimension = reader.dimension();
  content.count = reader.read_count();
  const int field_count = reader.read_header_integer();
  if (field_count < 1 || field_count > kMaxFields) reader.fail("field count " + std::to_string(field_count) + " out of range");
  int reals_per_row = 0;
  for (int i = 0; i < field_count; ++i) {
    const int type = reader.read_header_integer();
    if (type < 1 || type > 4) reader.fail("unknown solution type " + std::to_string(type));
    SolutionField& field = content.fields.emplace_back(SolutionField{static_cast<SolutionKind>(type), content.dimension, {}});
    reals_per_row += field.components();
  }
  reader.expect_records(content.count, 0, reals_per_row);
  const auto [first, last] = run.of(content.count);
  for (SolutionField& field : content.fields) field.values.reserve(reader.reserve_hint(last - first) * field.components());
  reader.skip_records(first, 0, reals_per_row);
  for (Index row = first; row < last; ++row)
    for (SolutionField& field : content.fields)
      for (int c = 0; c < field.components(); ++c) {
        double value = reader.read_real(row);
        if (!std::isfinite(value)) reader.fail("value is not finite", row);
        field.values.push_back(value);
      }
  reader.skip_records(content.count - last, 0, reals_per_row);
}

template <class Reader>
SolutionFileContent read_solution(Reader&& reader, const RecordRun& run) {
  SolutionFileContent content;
  bool found = false;
  while (reader.next_keyword()) {
    if (reader.keyword_code() != gamma::kSolAtVertices) {
      reader.skip_keyword();
      continue;
    }
    if (found) reader.fail("keyword appears twice");
    found = true;
    read_sol_at_vertices(reader, content, run);
  }
  if (!found) throw Error(reader.path() + ": SolAtVertices: missing");
  return content;
}

// The SolAtVertices header (the field count, then each field's type code) and the reals per row.
std::pair<std::vector<int>, int> sol_at_vertices_header(const std::vector<SolutionField>& fields) {
  std::vector<int> header{static_cast<int>(fields.size())};
  int reals_per_row = 0;
  for (const SolutionField& field : fields) {
    header.push_back(static_cast<int>(field.kind));
    reals_per_row += field.components();
  }
  return {header, reals_per_row};
}

template <class Writer>
void write_solution(Writer&& out, const SolutionFileContent& content) {
  const auto [header, reals_per_row] = sol_at_vertices_header(content.fields);
  out.begin_keyword(gamma::kSolAtVertices, content.count, 0, reals_per_row, header);
  for (Index row = 0; row < content.count; ++row) {
    for (const SolutionField& field : content.fields) {
      const auto components = static_cast<std::size_t>(field.components());
      for (std::size_t c = 0; c < components; ++c) out.write_real(field.values[row * components + c]);
    }
    out.end_record();
  }
  out.finish();
}

// Positive definiteness of a symmetric matrix in the on-disk order, by its LDL^T factorization
// (every pivot positive; NaN fails too).
bool is_positive_definite(const double* m, int dimension) {
  if (dimension == 2) {
    const double d1 = m[0];
    return d1 > 0 && m[2] - m[1] * m[1] / d1 > 0;
  }
  const double a11 = m[0], a12 = m[1], a22 = m[2], a13 = m[3], a23 = m[4], a33 = m[5];
  const double d1 = a11;
  if (!(d1 > 0)) return false;
  const double l21 = a12 / d1, d2 = a22 - l21 * a12;
  if (!(d2 > 0)) return false;
  const double l31 = a13 / d1, l32 = (a23 - l31 * a12) / d2;
  return a33 - l31 * a13 - l32 * l32 * d2 > 0;
}

}  // namespace

int SolutionField::components() const {
  switch (kind) {
    case SolutionKind::kScalar: return 1;
    case SolutionKind::kVector: return dimension;
    case SolutionKind::kSymmetricMatrix: return dimension * (dimension + 1) / 2;
    case SolutionKind::kMatrix: return dimension * dimension;
  }
  return 1;
}

Index SolutionField::count() const { return static_cast<Index>(values.size() / static_cast<std::size_t>(components())); }

SolutionFileContent read_solution_file(const std::string& path) { return read_solution_file_run(path, {}); }  // (one run: the whole)

SolutionFileContent read_solution_file_run(const std::string& path, const RecordRun& run) {
  return gamma::is_binary_file(path) ? read_solution(gamma::BinaryKeywordReader(path), run)
                                     : read_solution(gamma::TextKeywordReader(path), run);
}

void write_solution_file(const std::string& path, const SolutionFileContent& content, int gamma_version) {
  const std::string extension = file_extension(path);
  if (extension != ".sol" && extension != ".solb") throw Error(path + ": a solution file ends in .sol or .solb");
  if (content.dimension != 2 && content.dimension != 3)
    throw Error(path + ": solution dimension must be 2 or 3, not " + std::to_string(content.dimension));
  for (std::size_t i = 0; i < content.fields.size(); ++i) {
    const SolutionField& field = content.fields[i];
    if (field.dimension != content.dimension || field.values.size() != static_cast<std::size_t>(content.count) * field.components())
      throw Error(path + ": solution field " + one_based(i) + " does not hold " + std::to_string(content.count) + " rows of dimension " +
                  std::to_string(content.dimension));
  }
  if (content.fields.empty()) throw Error(path + ": a solution file needs at least one field");
  if (extension == ".solb")
    write_solution(gamma::BinaryKeywordWriter(path, gamma::resolve_version(path, gamma_version, content.count, 3), content.dimension),
                   content);
  else
    write_solution(gamma::TextKeywordWriter(path, gamma::resolve_version(path, gamma_version, content.count, 2), content.dimension),
                   content);
}

SolutionRowsLayout write_solution_skeleton(const std::string& path, int dimension, Index count, const std::vector<SolutionKind>& kinds) {
  std::vector<SolutionField> fields;
  for (SolutionKind kind : kinds) fields.push_back({kind, dimension, {}});
  const auto [header, reals_per_row] = sol_at_vertices_header(fields);
  gamma::BinaryKeywordWriter out(path, gamma::resolve_version(path, 0, count, 3), dimension);
  out.begin_keyword(gamma::kSolAtVertices, count, 0, reals_per_row, header);
  const SolutionRowsLayout layout{out.position(), static_cast<std::uint64_t>(reals_per_row) * sizeof(double)};  // version 3 or 4
  out.leave_records(layout.row_bytes * static_cast<std::uint64_t>(count));
  out.finish();
  return layout;
}

const SolutionField* SolutionFileContent::first_of_kind(SolutionKind kind) const {
  for (const SolutionField& field : fields)
    if (field.kind == kind && (kind != SolutionKind::kSymmetricMatrix || field.dimension == dimension)) return &field;
  return nullptr;
}

void add_metric_of_sizes(SolutionFileContent& content, const std::string& path, Index first_row) {
  const SolutionField* sizes = content.first_of_kind(SolutionKind::kScalar);
  if (content.first_of_kind(SolutionKind::kSymmetricMatrix) || !sizes) return;
  const int d = content.dimension;
  SolutionField metric{SolutionKind::kSymmetricMatrix, d, {}};
  metric.values.reserve(sizes->values.size() * static_cast<std::size_t>(d * (d + 1) / 2));
  for (std::size_t vertex = 0; vertex < sizes->values.size(); ++vertex) {
    const double h = sizes->values[vertex];
    const std::string where = " at vertex " + std::to_string(static_cast<long long>(first_row) + static_cast<long long>(vertex) + 1);
    if (!std::isfinite(h)) throw Error(path + ": SolAtVertices: size" + where + " is not finite");
    if (!(h > 0)) throw Error(path + ": SolAtVertices: size" + where + " is not positive");
    for (int row = 0; row < d; ++row)  // the lower triangle row by row: the diagonal ends each row
      for (int column = 0; column <= row; ++column) metric.values.push_back(row == column ? 1 / (h * h) : 0.0);
  }
  content.fields.push_back(std::move(metric));
}

const SolutionField& checked_metric_field(const SolutionFileContent& content, const std::string& path, int dimension, Index file_node_count,
                                          Index first_row) {
  if (content.dimension != dimension)
    throw Error(path + ": Dimension: the solution is " + std::to_string(content.dimension) + "D but the mesh is " +
                std::to_string(dimension) + "D");
  const SolutionField* metric = content.first_of_kind(SolutionKind::kSymmetricMatrix);
  if (!metric) throw Error(path + ": SolAtVertices: no symmetric-matrix field (type 3), so no metric");
  if (content.count != file_node_count)
    throw Error(path + ": SolAtVertices: " + std::to_string(content.count) + " metrics for a mesh of " + std::to_string(file_node_count) +
                " nodes");
  const auto components = static_cast<std::size_t>(metric->components());
  for (Index vertex = 0; vertex < metric->count(); ++vertex) {
    const double* m = &metric->values[vertex * components];
    const std::string where = " at vertex " + std::to_string(static_cast<long long>(first_row) + static_cast<long long>(vertex) + 1);
    for (std::size_t c = 0; c < components; ++c)
      if (!std::isfinite(m[c])) throw Error(path + ": SolAtVertices: metric" + where + " is not finite");
    if (!is_positive_definite(m, dimension)) throw Error(path + ": SolAtVertices: metric" + where + " is not positive definite");
  }
  return *metric;
}

}  // namespace hocav
