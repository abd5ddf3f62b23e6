#include "cli/command_support.hpp"

#include "io/mesh_file.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

// Curving meshes this large takes long enough to show its progress.
constexpr Index kProgressVertices = 20000;

}  // namespace

template <int D>
CurvingProgress::CurvingProgress(const Mesh<D>& mesh, int passes, bool wanted) {
  if (!wanted || !stderr_is_terminal() || mesh.vertex_count() <= kProgressVertices) return;
  total_ = static_cast<double>(volume_vertices(mesh).size()) * passes;
  line_ = std::make_unique<ProgressLine>(std::cerr, "curving", "vertices", total_);
}

void CurvingProgress::attach(CurvingOptions& options) {
  if (line_) options.progress = [this](double fraction) { line_->update(fraction * total_); };
}

void CurvingProgress::complete() {
  if (line_) line_->complete();
}

void print_curving_round(const DistributedCurvingRound& figures) {
  std::cerr << "distributed: round " << figures.round << " of " << figures.rounds << ": " << process_count() << " parts, "
            << figures.interface_faces << " interface faces, " << figures.interface_vertices << " vertices on the interfaces, "
            << figures.cavities << " cavities";
  if (figures.round > 1) std::cerr << ", " << figures.old_interface_vertices_frozen_again << " old interface vertices frozen again";
  std::cerr << ", " << figures.bytes_sent << " bytes sent, " << figures.seconds << " s\n";
}

template CurvingProgress::CurvingProgress(const Mesh<2>&, int, bool);
template CurvingProgress::CurvingProgress(const Mesh<3>&, int, bool);

}  // namespace hocav
