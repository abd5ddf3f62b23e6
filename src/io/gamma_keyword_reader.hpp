// Keyword-by-keyword readers of Gamma/Medit files, ASCII and binary, with one interface so the mesh
// and solution readers parse each keyword once (as templates over the reader):
//   next_keyword()         moves to the next keyword, consuming MeshVersionFormatted and Dimension
//                          on the way; false at End or at the end of the file
//   skip_keyword()         skips the current keyword's data, warning once per keyword name
//   read_count()           the entity count that opens a keyword's data
//   read_header_integer()  a small integer of a keyword header (solution type codes)
//   expect_records(...)    before reading `count` records: binary checks they fit in the block
//   skip_records(count, integers, reals)
//                          passes over `count` records of that many integers and reals (binary:
//                          a seek; text: the tokens read and dropped)
//   reserve_hint(count)    how many records to reserve once expected: all of them when the binary
//                          block holds them, at most 2^20 for text (vectors grow past it)
//   read_integer(entity), read_real(entity)
//   fail(what, entity)     throws Error "<file>: <keyword>: <what>, entity N[, line L]"
// The binary layout (endianness code, 32/64-bit positions, counts, integers and reals by version) is
// in docs/formats.md, "Binary layout". Counts are checked against the bytes left before anything is
// allocated from them; NextPos must move forward inside the file, so a corrupt chain cannot loop.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "base/index.hpp"
#include "io/text_scanner.hpp"

namespace hocav::gamma {

// True when the file starts with a binary endianness code (1, or 1 byte-swapped). Throws Error when
// the file cannot be opened.
bool is_binary_file(const std::string& path);

// What the two readers share: the file header, the current keyword, warnings.
class KeywordReaderState {
 public:
  KeywordReaderState(const KeywordReaderState&) = delete;  // the text reader keeps views into its buffer
  KeywordReaderState& operator=(const KeywordReaderState&) = delete;
  const std::string& path() const { return path_; }
  int version() const { return version_; }
  int dimension() const { return dimension_; }  // 0 until a Dimension keyword was read
  int keyword_code() const { return keyword_code_; }
  const std::string& keyword() const { return keyword_; }
  // No warnings from here on (a process that reads one piece of a file another also warns about).
  void silence_warnings() { warnings_ = false; }

 protected:
  explicit KeywordReaderState(std::string path) : path_(std::move(path)) {}
  // Validate and record the header values; `fail` reports in the reader's own style.
  template <class Reader>
  void set_version(Reader& reader, std::int64_t version);
  template <class Reader>
  void set_dimension(Reader& reader, std::int64_t dimension);
  void warn_skipped();

  std::string path_;
  int version_ = 0;
  int dimension_ = 0;
  int keyword_code_ = 0;
  std::string keyword_;  // printable ASCII, 40 bytes at most
  bool warnings_ = true;

 private:
  std::set<std::string> warned_;
};

class TextKeywordReader : public KeywordReaderState {
 public:
  explicit TextKeywordReader(const std::string& path);

  bool next_keyword();
  void skip_keyword(bool warn = true);
  Index read_count();
  int read_header_integer();
  void expect_records(Index, int, int) {}  // text has no sizes to check ahead
  void skip_records(Index count, int integers, int reals);
  std::size_t reserve_hint(Index count) const { return std::min(static_cast<std::size_t>(count), std::size_t{1} << 20); }
  std::int64_t read_integer(Index) { return scanner_.next_integer(keyword_); }
  double read_real(Index) { return scanner_.next_real(keyword_); }
  [[noreturn]] void fail(std::string_view what, Index entity = kNoIndex) const;

 private:
  TextScanner scanner_;
  std::string_view pending_;  // a token read ahead while skipping: the next keyword
};

class BinaryKeywordReader : public KeywordReaderState {
 public:
  explicit BinaryKeywordReader(const std::string& path);

  bool next_keyword();
  void skip_keyword(bool warn = true);
  Index read_count();
  int read_header_integer();
  void expect_records(Index count, int integers, int reals);
  void skip_records(Index count, int integers, int reals);
  std::size_t reserve_hint(Index count) const { return static_cast<std::size_t>(count); }
  std::int64_t read_integer(Index) { return version_ >= 4 ? read_word<std::int64_t>() : read_word<std::int32_t>(); }
  double read_real(Index) { return version_ == 1 ? read_word<float>() : read_word<double>(); }
  [[noreturn]] void fail(std::string_view what, Index entity = kNoIndex) const;

 private:
  template <class Word>
  Word read_word() {
    Word value;
    std::memcpy(&value, take(sizeof(Word)), sizeof(Word));
    return swap_bytes_ ? byte_swapped(value) : value;
  }
  template <class Word>
  static Word byte_swapped(Word value) {
    if constexpr (sizeof(Word) == 4)
      return std::bit_cast<Word>(__builtin_bswap32(std::bit_cast<std::uint32_t>(value)));
    else
      return std::bit_cast<Word>(__builtin_bswap64(std::bit_cast<std::uint64_t>(value)));
  }
  std::int64_t read_position() { return version_ >= 3 ? read_word<std::int64_t>() : read_word<std::int32_t>(); }
  std::uint64_t record_bytes(int integers, int reals) const {
    return static_cast<std::uint64_t>(integers) * (version_ >= 4 ? 8 : 4) + static_cast<std::uint64_t>(reals) * (version_ == 1 ? 4 : 8);
  }
  std::uint64_t position() const { return buffer_offset_ + cursor_; }
  void seek(std::uint64_t position);
  // The next `bytes` bytes of the file; refills the buffer when needed, fails past the block's end.
  const char* take(std::size_t bytes) {
    if (cursor_ + bytes > filled_ || position() + bytes > block_end_) return refill(bytes);
    const char* data = buffer_.data() + cursor_;
    cursor_ += bytes;
    return data;
  }
  const char* refill(std::size_t bytes);

  std::ifstream in_;
  std::uint64_t file_size_ = 0;
  bool swap_bytes_ = false;
  std::vector<char> buffer_;
  std::uint64_t buffer_offset_ = 0;  // file offset of buffer_[0]
  std::size_t cursor_ = 0, filled_ = 0;
  std::uint64_t block_end_ = 0;   // NextPos of the current block, or the file size for the last one
  std::uint64_t next_block_ = 0;  // where the next keyword starts; 0 after the last one
};

}  // namespace hocav::gamma
