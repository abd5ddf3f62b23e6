#include "io/temporary_files.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>

#include "base/error.hpp"

namespace hocav {
namespace {

// The signal handler may only read fixed memory and call unlink: paths live in fixed slots, a slot
// is published (in_use) only once its path is complete.
constexpr std::size_t kSlots = 64, kPathBytes = 4096;
constexpr std::size_t kLongestKeptExtension = 16;
constexpr int kCleanedSignals[] = {SIGINT, SIGTERM, SIGHUP};
std::array<std::array<char, kPathBytes>, kSlots> slot_paths;
std::array<std::atomic<bool>, kSlots> slot_in_use;
std::mutex slots_mutex;

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  for (std::size_t slot = 0; slot < kSlots; ++slot)
    if (slot_in_use[slot].load()) ::unlink(slot_paths[slot].data());
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

void install_handler_once() {
  static std::once_flag installed;
  std::call_once(installed, [] {
    for (int signal_number : kCleanedSignals) {
      struct sigaction action {};
      action.sa_handler = remove_temporaries_and_reraise;
      sigemptyset(&action.sa_mask);
      struct sigaction previous {};
      ::sigaction(signal_number, nullptr, &previous);
      if (previous.sa_handler != SIG_IGN) ::sigaction(signal_number, &action, nullptr);  // nohup stays nohup
    }
  });
}

void remember(const std::string& path) {
  if (path.size() >= kPathBytes) throw Error(path + ": path too long");
  install_handler_once();
  std::lock_guard lock(slots_mutex);
  for (std::size_t slot = 0; slot < kSlots; ++slot)
    if (!slot_in_use[slot].load()) {
      std::memcpy(slot_paths[slot].data(), path.c_str(), path.size() + 1);
      slot_in_use[slot].store(true);
      return;
    }
  throw Error(path + ": too many output files at once");
}

}  // namespace

std::string new_temporary_path(const std::string& target) {
  static std::atomic<int> counter{0};
  const std::filesystem::path target_path(target);
  std::string extension = target_path.extension().string();
  if (extension.size() > kLongestKeptExtension) extension.clear();
  const std::string name = ".hocav-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tmp" + extension;
  std::string path = (target_path.parent_path() / name).string();
  remember(path);
  return path;
}

void forget_temporary(const std::string& temporary) {
  std::lock_guard lock(slots_mutex);
  for (std::size_t slot = 0; slot < kSlots; ++slot)
    if (slot_in_use[slot].load() && temporary == slot_paths[slot].data()) slot_in_use[slot].store(false);
}

void remove_temporary(const std::string& temporary) {
  std::remove(temporary.c_str());
  forget_temporary(temporary);
}

}  // namespace hocav
