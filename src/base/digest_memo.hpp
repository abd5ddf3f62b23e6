// Values of pure computations remembered by a digest of everything they read: asked again with the
// same inputs, bit for bit, a computation returns the value it returned the first time, so a caller
// that remembers gives the same output as one that recomputes. The curved passes measure the same
// unchanged edges and elements pass after pass (docs/adaptation.md §Curved passes).
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

namespace hocav {

// A 128-bit digest of a sequence of 64-bit words (two independent multiply–rotate streams, mixed at
// the end); the words are the inputs' bit patterns.
class Digest {
 public:
  struct Value {
    std::uint64_t first = 0, second = 0;
    bool operator==(const Value&) const = default;
  };

  // `kind` names the computation, so two computations with the same inputs differ.
  explicit Digest(std::uint64_t kind) { add_word(kind); }

  void add_word(std::uint64_t word) {
    first_ = std::rotl((first_ ^ word) * 0x9e3779b97f4a7c15ULL, 31);
    second_ = std::rotl(second_ + word * 0xc2b2ae3d27d4eb4fULL, 27) * 0x165667b19e3779f9ULL;
  }
  void add(double x) { add_word(std::bit_cast<std::uint64_t>(x)); }
  template <typename Values>
  void add_all(const Values& values) {
    for (double x : values) add(x);
  }

  // (Its first word is odd, never the 0 that marks a memo's empty slot.)
  Value value() const { return {mix(first_ ^ second_) | 1, mix(second_ + 0x94d049bb133111ebULL * first_)}; }

 private:
  // SplitMix64's finalizer: every input bit reaches every output bit.
  static std::uint64_t mix(std::uint64_t x) {
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  }

  std::uint64_t first_ = 0x243f6a8885a308d3ULL, second_ = 0x13198a2e03707344ULL;
};

// Remembered values by digest, safe to use from several threads (the table is cut into shards, each
// with its own lock). Two threads asking the same new digest may both compute it: the same value.
class DigestMemo {
 public:
  // The value remembered for `key`, or none.
  std::optional<double> find(const Digest::Value& key) const;
  void remember(const Digest::Value& key, double value);

  // The value remembered for `key`, else compute()'s, remembered.
  template <typename Compute>
  double value(const Digest::Value& key, const Compute& compute) {
    if (const std::optional<double> known = find(key)) return *known;
    const double computed = compute();
    remember(key, computed);
    return computed;
  }

 private:
  // Open addressing with linear probing in a power-of-two table, at most half full.
  struct Shard {
    std::mutex mutex;
    std::vector<Digest::Value> keys;  // empty slots: first word 0
    std::vector<double> values;
    std::size_t used = 0;
  };
  static constexpr std::size_t kShards = 64;
  Shard& shard_of(const Digest::Value& key) const { return shards_[key.first >> 58]; }
  mutable std::array<Shard, kShards> shards_;
};

}  // namespace hocav
