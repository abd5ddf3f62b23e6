#include "base/memory_budget.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <limits>

#include "base/error.hpp"
#include "base/index.hpp"

namespace hocav {
namespace {

std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  return text;
}

std::string count_text(double count) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", count);
  return text;
}

}  // namespace

long long peak_resident_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<long long>(usage.ru_maxrss) * 1024;  // Linux gives KiB
}

double physical_memory_bytes() { return static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGE_SIZE)); }

void check_memory_fits(const std::string& job, double elements, double bytes_per_element) {
  if (elements > static_cast<double>(std::numeric_limits<Index>::max()))
    throw Error(job + ": about " + count_text(elements) + " elements, more than the " +
                count_text(static_cast<double>(std::numeric_limits<Index>::max())) + " hocav can index");
  const double needed = elements * bytes_per_element, available = physical_memory_bytes();
  if (needed > available)
    throw Error(job + ": about " + count_text(elements) + " elements would need about " + gigabytes(needed) + ", more than the " +
                gigabytes(available) + " of this machine");
}

}  // namespace hocav
