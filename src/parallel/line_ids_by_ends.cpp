#include "parallel/line_ids_by_ends.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "base/error.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

template <int D>
FaceKey<2> ends_of(const MeshPart<D>& part, Index l) {
  const auto [a, b] = part.mesh.line(l);
  return sorted_key<2>({part.global_ids[static_cast<std::size_t>(a)], part.global_ids[static_cast<std::size_t>(b)]});
}

}  // namespace

template <int D>
std::vector<KnownLine> known_lines(const MeshPart<D>& part, const std::vector<Index>& ids) {
  if (ids.size() != static_cast<std::size_t>(part.mesh.line_count())) throw Error("known lines: not one id per line");
  std::vector<KnownLine> known;
  for (Index l = 0; l < part.mesh.line_count(); ++l) known.push_back({ends_of(part, l), ids[static_cast<std::size_t>(l)]});
  return known;
}

template <int D>
std::vector<Index> line_ids_among(const MeshPart<D>& part, std::vector<KnownLine> lines) {
  const auto by_ends = [](const KnownLine& x, const KnownLine& y) { return x.ends < y.ends; };
  std::sort(lines.begin(), lines.end(), by_ends);
  std::vector<Index> ids;
  for (Index l = 0; l < part.mesh.line_count(); ++l) {
    const KnownLine wanted{ends_of(part, l), kNoIndex};
    const auto found = std::lower_bound(lines.begin(), lines.end(), wanted, by_ends);
    if (found == lines.end() || found->ends != wanted.ends)
      throw Error("line ids: no known line joins vertices " + one_based(wanted.ends[0]) + " and " + one_based(wanted.ends[1]));
    ids.push_back(found->id);
  }
  return ids;
}

template <int D>
std::vector<Index> line_ids_by_ends(const MeshPart<D>& part, const std::vector<KnownLine>& known) {
  return line_ids_among(part, all_gather_values_joined(known));
}

template std::vector<KnownLine> known_lines(const MeshPart<2>&, const std::vector<Index>&);
template std::vector<KnownLine> known_lines(const MeshPart<3>&, const std::vector<Index>&);
template std::vector<Index> line_ids_among(const MeshPart<2>&, std::vector<KnownLine>);
template std::vector<Index> line_ids_among(const MeshPart<3>&, std::vector<KnownLine>);
template std::vector<Index> line_ids_by_ends(const MeshPart<2>&, const std::vector<KnownLine>&);
template std::vector<Index> line_ids_by_ends(const MeshPart<3>&, const std::vector<KnownLine>&);

}  // namespace hocav
