// Built without MPI (HOCAV_WITH_MPI off): always one process, which never sends.
#include <cstdlib>
#include <string>

#include "base/error.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

[[noreturn]] void no_mpi() { throw Error("hocav was built without MPI (docs/distributed.md): it runs as one process"); }

}  // namespace

MpiSession::MpiSession(int&, char**&) {}
MpiSession::~MpiSession() = default;
bool built_with_mpi() { return false; }
int process_rank() { return 0; }
int process_count() { return 1; }
void send_bytes(int, const std::vector<std::byte>&) { no_mpi(); }
std::vector<std::byte> receive_bytes(int) { no_mpi(); }
void broadcast_bytes(std::vector<std::byte>&) {}
std::vector<std::vector<std::byte>> exchange_bytes(const std::vector<std::vector<std::byte>>& outgoing) {
  if (outgoing.size() != 1) throw Error("an exchange between processes addresses " + std::to_string(outgoing.size()) + " of 1");
  return outgoing;
}
std::vector<std::vector<std::byte>> all_gather_bytes(const std::vector<std::byte>& bytes) { return {bytes}; }
void abort_processes(int exit_code) { std::exit(exit_code); }

}  // namespace hocav
