// The processes of a distributed run (docs/distributed.md): MPI's world when hocav runs under
// mpirun, one process otherwise or when built without MPI (the CMake option HOCAV_WITH_MPI).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

#include "base/index.hpp"

namespace hocav {

// Starts MPI when the process was launched by mpirun (its environment says so) and ends it when
// destroyed; else does nothing, so that a plain `hocav` never starts MPI.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

 private:
  bool started_ = false;
};

bool built_with_mpi();
int process_rank();   // 0 for one process
int process_count();  // 1 for one process

// Point to point and from rank 0 to all, any size (sent in pieces MPI's int counts can hold).
void send_bytes(int to, const std::vector<std::byte>& bytes);
std::vector<std::byte> receive_bytes(int from);

// The same, adding the message's size to `volume` (a distributed run's communication figures).
inline void send_bytes(int to, const std::vector<std::byte>& bytes, long long& volume) {
  volume += static_cast<long long>(bytes.size());
  send_bytes(to, bytes);
}
inline std::vector<std::byte> receive_bytes(int from, long long& volume) {
  std::vector<std::byte> bytes = receive_bytes(from);
  volume += static_cast<long long>(bytes.size());
  return bytes;
}
void broadcast_bytes(std::vector<std::byte>& bytes);

// Every process at once sends outgoing[r] to process r and gets what each sent it: the result's
// entry r is process r's message to this one (a process's message to itself included).
std::vector<std::vector<std::byte>> exchange_bytes(const std::vector<std::vector<std::byte>>& outgoing);

// Every process's `bytes`, in rank order, on every process.
std::vector<std::vector<std::byte>> all_gather_bytes(const std::vector<std::byte>& bytes);

// Ends every process with `exit_code` (an error on one process would leave the others waiting).
[[noreturn]] void abort_processes(int exit_code);

template <typename T>
std::vector<std::byte> bytes_of_values(const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::vector<std::byte> bytes(values.size() * sizeof(T));
  if (!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

template <typename T>
std::vector<T> values_of_bytes(const std::vector<std::byte>& bytes) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::vector<T> values(bytes.size() / sizeof(T));
  if (!values.empty()) std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
  return values;
}

// Rank 0's `values` to every process.
template <typename T>
void broadcast_values(std::vector<T>& values) {
  std::vector<std::byte> bytes = bytes_of_values(values);
  broadcast_bytes(bytes);
  values = values_of_bytes<T>(bytes);
}

// One message of values per process, as exchange_bytes takes them.
template <typename T>
std::vector<std::vector<std::byte>> bytes_of_messages(const std::vector<std::vector<T>>& messages) {
  std::vector<std::vector<std::byte>> bytes;
  for (const std::vector<T>& message : messages) bytes.push_back(bytes_of_values(message));
  return bytes;
}

// Every process at once: messages of values, as exchange_bytes sends them; what each process sent
// this one, in rank order.
template <typename T>
std::vector<std::vector<T>> exchange_values(const std::vector<std::vector<T>>& outgoing) {
  std::vector<std::vector<T>> arrived;
  for (const std::vector<std::byte>& bytes : exchange_bytes(bytes_of_messages(outgoing))) arrived.push_back(values_of_bytes<T>(bytes));
  return arrived;
}

// The same, what arrived put end to end in rank order.
template <typename T>
std::vector<T> exchange_values_joined(const std::vector<std::vector<T>>& outgoing) {
  std::vector<T> joined;
  for (const std::vector<T>& values : exchange_values(outgoing)) joined.insert(joined.end(), values.begin(), values.end());
  return joined;
}

// Every process's `value`, in rank order, on every process.
template <typename T>
std::vector<T> all_gather_value(const T& value) {
  std::vector<T> values;
  for (const std::vector<std::byte>& bytes : all_gather_bytes(bytes_of_values(std::vector<T>{value})))
    values.push_back(values_of_bytes<T>(bytes).at(0));
  return values;
}

// Every process's `values`, in rank order, on every process.
template <typename T>
std::vector<std::vector<T>> all_gather_values(const std::vector<T>& values) {
  std::vector<std::vector<T>> all;
  for (const std::vector<std::byte>& bytes : all_gather_bytes(bytes_of_values(values))) all.push_back(values_of_bytes<T>(bytes));
  return all;
}

// Every process's `values` put end to end in rank order, on every process.
template <typename T>
std::vector<T> all_gather_values_joined(const std::vector<T>& values) {
  std::vector<T> joined;
  for (const std::vector<std::byte>& bytes : all_gather_bytes(bytes_of_values(values))) {
    const std::vector<T> from = values_of_bytes<T>(bytes);
    joined.insert(joined.end(), from.begin(), from.end());
  }
  return joined;
}

// The number of entities the processes before this one count, and the sum over all, of every
// process's `count`.
struct CountOffset {
  Index before = 0, total = 0;
};
inline CountOffset offset_over_processes(Index count) {
  CountOffset offset;
  const std::vector<Index> counts = all_gather_value(count);
  for (int r = 0; r < process_count(); ++r) {
    if (r < process_rank()) offset.before += counts[static_cast<std::size_t>(r)];
    offset.total += counts[static_cast<std::size_t>(r)];
  }
  return offset;
}

// The sum of every process's `value`, on every process.
template <typename T>
T sum_over_processes(const T& value) {
  T sum{};
  for (const T& each : all_gather_value(value)) sum += each;
  return sum;
}

// The largest of every process's `value`, on every process.
template <typename T>
T max_over_processes(const T& value) {
  T largest = value;
  for (const T& each : all_gather_value(value)) largest = std::max(largest, each);
  return largest;
}

template <typename T>
void send_values(int to, const std::vector<T>& values) {
  send_bytes(to, bytes_of_values(values));
}

template <typename T>
std::vector<T> receive_values(int from) {
  return values_of_bytes<T>(receive_bytes(from));
}

}  // namespace hocav
