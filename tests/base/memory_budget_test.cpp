#include "base/memory_budget.hpp"

#include <gtest/gtest.h>

#include <string>

#include "base/error.hpp"

namespace hocav {
namespace {

std::string refusal(double elements, double bytes_per_element) {
  try {
    check_memory_fits("the job", elements, bytes_per_element);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(MemoryBudget, KnowsTheMachine) { EXPECT_GT(physical_memory_bytes(), 1e8); }

TEST(MemoryBudget, RefusesAJobLargerThanTheMachineWithItsEstimate) {
  const double machine = physical_memory_bytes();
  EXPECT_EQ(refusal(1e6, kCurvingBytesPerElement), "");
  const std::string message = refusal(1e6, 2 * machine / 1e6);  // twice the machine
  EXPECT_NE(message.find("the job: about 1e+06 elements would need about "), std::string::npos) << message;
  EXPECT_NE(message.find("GB of this machine"), std::string::npos) << message;
}

TEST(MemoryBudget, RefusesMoreElementsThan32BitIndices) {
  EXPECT_NE(refusal(4.8e10, 1e-9).find("more than the 2.15e+09 hocav can index"), std::string::npos);
}

}  // namespace
}  // namespace hocav
