#include "parallel/piece_input_check.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "base/error.hpp"
#include "io/gamma_mesh.hpp"
#include "io/record_run.hpp"
#include "mesh/inverted_input.hpp"
#include "mesh/measure.hpp"
#include "mesh/open_boundary.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

// Collective: the first element of non-positive measure of every piece, by its file id, refused by
// the process that holds it (`bad` its local id in `mesh`, or kNoIndex; `first` the file id of the
// piece's first element).
template <int D>
void refuse_first_bad_element(const Mesh<D>& mesh, Index bad, Index first, const std::string& path) {
  constexpr long long kNone = std::numeric_limits<long long>::max();
  const long long own = bad == kNoIndex ? kNone : static_cast<long long>(first) + bad;
  const std::vector<long long> firsts = all_gather_value(own);
  const long long first_bad = *std::min_element(firsts.begin(), firsts.end());
  if (first_bad == kNone || own != first_bad) return;
  throw Error(path + ": inconsistent mesh: element " + one_based(first_bad) + " has non-positive P1 measure " +
              std::to_string(element_measure(mesh, bad)) + " (see hocav stats)");
}

}  // namespace

template <int D>
void prepare_input_piece(MeshFilePiece<D>& piece, const std::string& path, const std::function<void(const std::string&)>& warn) {
  Mesh<D>& mesh = piece.part.mesh;
  long long inverted = 0;
  Index bad = kNoIndex;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const double measure = element_measure(mesh, k);
    if (measure < 0) ++inverted;
    if (!(measure > 0) && bad == kNoIndex) bad = k;
  }
  const bool say = process_rank() == 0 && warn;
  if (sum_over_processes(inverted) == piece.element_count) {
    reorient_every_element(mesh);
    if (say) warn(inverted_input_warning(path, piece.element_count));
  } else {
    refuse_first_bad_element(mesh, bad, slice_start(piece.element_count, process_rank(), process_count()), path);
  }
  const Index own_added = add_facets_on_open_faces(mesh, 0);
  const std::vector<Index> added = all_gather_value(own_added);
  // (Their file ids: after the file's facets, rank after rank, as the serial preparation appends them.)
  Index next = piece.facet_count + std::accumulate(added.begin(), added.begin() + process_rank(), Index{0});
  for (Index i = 0; i < own_added; ++i) piece.facet_ids.push_back(next++);
  const long long total = std::accumulate(added.begin(), added.end(), 0LL);
  if (say && total > 0) warn(open_boundary_warning(path, total));
}

template void prepare_input_piece(MeshFilePiece<2>&, const std::string&, const std::function<void(const std::string&)>&);
template void prepare_input_piece(MeshFilePiece<3>&, const std::string&, const std::function<void(const std::string&)>&);

}  // namespace hocav
