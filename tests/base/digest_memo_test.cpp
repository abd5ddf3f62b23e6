#include "base/digest_memo.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

namespace hocav {
namespace {

Digest::Value digest_of(std::uint64_t kind, std::initializer_list<double> values) {
  Digest digest(kind);
  digest.add_all(values);
  return digest.value();
}

TEST(Digest, DiffersWithTheKindTheOrderAndEveryBit) {
  const Digest::Value base = digest_of(1, {1.0, 2.0});
  EXPECT_EQ(digest_of(1, {1.0, 2.0}), base);
  EXPECT_NE(digest_of(2, {1.0, 2.0}), base);
  EXPECT_NE(digest_of(1, {2.0, 1.0}), base);
  EXPECT_NE(digest_of(1, {1.0, 2.0, 0.0}), base);
  EXPECT_NE(digest_of(1, {0.0}), digest_of(1, {-0.0}));
  EXPECT_NE(digest_of(1, {1.0, std::nextafter(2.0, 3.0)}), base);
}

TEST(DigestMemo, ComputesEachDigestOnce) {
  DigestMemo memo;
  int computed = 0;
  const auto compute = [&](double value) {
    return [&computed, value] {
      ++computed;
      return value;
    };
  };
  EXPECT_EQ(memo.value(digest_of(1, {1.0}), compute(10)), 10);
  EXPECT_EQ(memo.value(digest_of(1, {1.0}), compute(99)), 10);
  EXPECT_EQ(memo.value(digest_of(1, {2.0}), compute(20)), 20);
  EXPECT_EQ(computed, 2);
  EXPECT_FALSE(memo.find(digest_of(1, {3.0})).has_value());
  memo.remember(digest_of(1, {1.0}), 55);  // a digest known already keeps its value
  EXPECT_EQ(memo.find(digest_of(1, {1.0})), 10);
}

TEST(DigestMemo, KeepsEveryValueAsItsTablesGrow) {
  DigestMemo memo;
  constexpr int kCount = 200000;
  for (int i = 0; i < kCount; ++i) memo.remember(digest_of(7, {static_cast<double>(i)}), 3.0 * i);
  for (int i = 0; i < kCount; ++i) ASSERT_EQ(memo.find(digest_of(7, {static_cast<double>(i)})), 3.0 * i) << i;
  EXPECT_FALSE(memo.find(digest_of(7, {-1.0})).has_value());
}

TEST(DigestMemo, GivesEachThreadTheValuesOfItsDigests) {
  DigestMemo memo;
  constexpr int kCount = 50000;
  std::vector<int> wrong(2, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < kCount; ++i) {
        const int key = t == 0 ? i : kCount - 1 - i;  // the threads meet halfway
        wrong[t] += memo.value(digest_of(3, {static_cast<double>(key)}), [key] { return 0.5 * key; }) != 0.5 * key;
      }
    });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(wrong, (std::vector<int>{0, 0}));
  for (int i = 0; i < kCount; ++i) ASSERT_EQ(memo.find(digest_of(3, {static_cast<double>(i)})), 0.5 * i);
}

}  // namespace
}  // namespace hocav
