#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>

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
  // PT-Scotch's threads call MPI while other threads of the process do (docs/distributed.md
  // §Partitioning): with less than MPI_THREAD_MULTIPLE its partitions on 4 processes hang.
  int provided = MPI_THREAD_SINGLE;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_MULTIPLE, &provided), "MPI_Init_thread");
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

std::vector<std::vector<std::byte>> exchange_bytes(const std::vector<std::vector<std::byte>>& outgoing) {
  const int count = process_count();
  if (static_cast<int>(outgoing.size()) != count)
    throw Error("an exchange between processes addresses " + std::to_string(outgoing.size()) + " of " + std::to_string(count));
  if (count == 1) return outgoing;
  std::vector<std::uint64_t> sizes_out(outgoing.size()), sizes_in(outgoing.size());
  for (std::size_t r = 0; r < outgoing.size(); ++r) sizes_out[r] = outgoing[r].size();
  check(MPI_Alltoall(sizes_out.data(), 1, MPI_UINT64_T, sizes_in.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD), "MPI_Alltoall");
  std::vector<std::vector<std::byte>> incoming(outgoing.size());
  std::vector<MPI_Request> requests;
  for (int r = 0; r < count; ++r) {
    incoming[r].resize(sizes_in[r]);
    for (std::size_t offset = 0; offset < sizes_in[r]; offset += kPieceBytes) {
      const auto piece = static_cast<int>(std::min(kPieceBytes, sizes_in[r] - offset));
      check(MPI_Irecv(incoming[r].data() + offset, piece, MPI_BYTE, r, 1, MPI_COMM_WORLD, &requests.emplace_back()), "MPI_Irecv");
    }
  }
  for (int r = 0; r < count; ++r)
    for (std::size_t offset = 0; offset < outgoing[r].size(); offset += kPieceBytes) {
      const auto piece = static_cast<int>(std::min(kPieceBytes, outgoing[r].size() - offset));
      // MPI's send buffers are not const in every version's interface; it only reads them.
      auto* data = const_cast<std::byte*>(outgoing[r].data()) + offset;
      check(MPI_Isend(data, piece, MPI_BYTE, r, 1, MPI_COMM_WORLD, &requests.emplace_back()), "MPI_Isend");
    }
  check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
  return incoming;
}

std::vector<std::vector<std::byte>> all_gather_bytes(const std::vector<std::byte>& bytes) {
  return exchange_bytes(std::vector<std::vector<std::byte>>(static_cast<std::size_t>(process_count()), bytes));
}

void abort_processes(int exit_code) {
  if (mpi_running()) MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::exit(exit_code);
}

}  // namespace hocav
