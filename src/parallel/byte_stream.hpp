// Arrays of plain values as one message between processes and back (docs/distributed.md
// §Migration): each array as its length and its bytes, read back in the order written.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

#include "base/error.hpp"

namespace hocav {

class ByteWriter {
 public:
  template <typename T>
  void put(std::span<const T> values) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::uint64_t count = values.size();
    append(&count, sizeof count);
    append(values.data(), values.size_bytes());
  }
  template <typename T>
  void put(const std::vector<T>& values) {
    put(std::span<const T>(values));
  }
  std::vector<std::byte> bytes;

 private:
  void append(const void* data, std::size_t size) {
    const auto* first = static_cast<const std::byte*>(data);
    bytes.insert(bytes.end(), first, first + size);
  }
};

class ByteReader {
 public:
  explicit ByteReader(const std::vector<std::byte>& bytes) : bytes_(bytes) {}
  template <typename T>
  std::vector<T> take() {
    std::uint64_t count = 0;
    copy(&count, sizeof count);
    if (count > (bytes_.size() - offset_) / sizeof(T)) throw Error("a message between processes is cut short");
    std::vector<T> values(count);
    copy(values.data(), count * sizeof(T));
    return values;
  }
  bool at_end() const { return offset_ == bytes_.size(); }

 private:
  void copy(void* out, std::size_t size) {
    if (size > bytes_.size() - offset_) throw Error("a message between processes is cut short");
    if (size > 0) std::memcpy(out, bytes_.data() + offset_, size);
    offset_ += size;
  }
  const std::vector<std::byte>& bytes_;
  std::size_t offset_ = 0;
};

}  // namespace hocav
