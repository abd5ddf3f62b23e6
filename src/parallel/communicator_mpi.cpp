#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "base/error.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

// The largest piece one MPI call moves (its counts are ints).
constexpr std::size_t kPieceBytes = std::size_t{1} << 30;

bool launched_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

bool mpi_running() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized && !finalized;
}

void check(int status, const char* what) {
  if (status != MPI_SUCCESS) throw Error(std::string("MPI failed in ") + what);
}

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  if (!launched_by_mpirun()) return;
  check(MPI_Init(&argc, &argv), "MPI_Init");
  started_ = true;
}

MpiSession::~MpiSession() {
  if (started_ && mpi_running()) MPI_Finalize();
}

bool built_with_mpi() { return true; }

int process_rank() {
  int rank = 0;
  if (mpi_running()) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int process_count() {
  int count = 1;
  if (mpi_running()) MPI_Comm_size(MPI_COMM_WORLD, &count);
  return count;
}

void send_bytes(int to, const std::vector<std::byte>& bytes) {
  const std::uint64_t size = bytes.size();
  check(MPI_Send(&size, 1, MPI_UINT64_T, to, 0, MPI_COMM_WORLD), "MPI_Send");
  for (std::size_t offset = 0; offset < bytes.size(); offset += kPieceBytes) {
    const auto piece = static_cast<int>(std::min(kPieceBytes, bytes.size() - offset));
    check(MPI_Send(bytes.data() + offset, piece, MPI_BYTE, to, 0, MPI_COMM_WORLD), "MPI_Send");
  }
}

std::vector<std::byte> receive_bytes(int from) {
  std::uint64_t size = 0;
  check(MPI_Recv(&size, 1, MPI_UINT64_T, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
  std::vector<std::byte> bytes(size);
  for (std::size_t offset = 0; offset < bytes.size(); offset += kPieceBytes) {
    const auto piece = static_cast<int>(std::min(kPieceBytes, bytes.size() - offset));
    check(MPI_Recv(bytes.data() + offset, piece, MPI_BYTE, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
  }
  return bytes;
}

void broadcast_bytes(std::vector<std::byte>& bytes) {
  std::uint64_t size = bytes.size();
  check(MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
  bytes.resize(size);
  for (std::size_t offset = 0; offset < bytes.size(); offset += kPieceBytes) {
    const auto piece = static_cast<int>(std::min(kPieceBytes, bytes.size() - offset));
    check(MPI_Bcast(bytes.data() + offset, piece, MPI_BYTE, 0, MPI_COMM_WORLD), "MPI_Bcast");
  }
}

void abort_processes(int exit_code) {
  if (mpi_running()) MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::exit(exit_code);
}

}  // namespace hocav
