#include "io/gamma_keyword_reader.hpp"

#include <algorithm>
#include <charconv>
#include <iostream>
#include <limits>
#include <utility>

#include "base/error.hpp"
#include "io/gamma_keywords.hpp"
#include "io/printable_excerpt.hpp"

namespace hocav::gamma {
namespace {

constexpr std::int32_t kNativeEndianCode = 1;
constexpr std::int32_t kSwappedEndianCode = 16777216;
constexpr std::size_t kReadChunkBytes = std::size_t{1} << 20;
// Past this many distinct skipped keywords the file is likely not a mesh at all: stop the noise.
constexpr std::size_t kMaxSkipWarnings = 4;

bool is_number(std::string_view token) {
  double value = 0;
  auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return (error == std::errc() || error == std::errc::result_out_of_range) && end == token.data() + token.size();
}

}  // namespace

bool is_binary_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open for reading");
  std::int32_t code = 0;
  in.read(reinterpret_cast<char*>(&code), sizeof code);
  return in.gcount() == sizeof code && (code == kNativeEndianCode || code == kSwappedEndianCode);
}

template <class Reader>
void KeywordReaderState::set_version(Reader& reader, std::int64_t version) {
  if (version < 1 || version > 4) reader.fail("unsupported version " + std::to_string(version) + " (1 to 4 are known)");
  version_ = static_cast<int>(version);
}

template <class Reader>
void KeywordReaderState::set_dimension(Reader& reader, std::int64_t dimension) {
  if (dimension != 2 && dimension != 3) reader.fail("dimension must be 2 or 3, found " + std::to_string(dimension));
  if (dimension_ != 0 && dimension_ != dimension) reader.fail("a second Dimension disagrees with the first");
  dimension_ = static_cast<int>(dimension);
}

void KeywordReaderState::warn_skipped() {
  if (!warnings_ || !warned_.insert(keyword_).second) return;
  const std::string where = "hocav: warning: " + path_ + ": ";
  if (warned_.size() <= kMaxSkipWarnings)
    std::cerr << where << "skipping keyword " << keyword_ << " (not used by hocav)\n";
  else if (warned_.size() == kMaxSkipWarnings + 1)
    std::cerr << where << "skipping more unknown keywords without naming them\n";
}

// ---- ASCII ----

TextKeywordReader::TextKeywordReader(const std::string& path) : KeywordReaderState(path), scanner_(path, '#') {}

bool TextKeywordReader::next_keyword() {
  while (true) {
    std::string_view token = pending_.empty() ? scanner_.next_token() : std::exchange(pending_, {});
    if (token.empty()) return false;
    if (is_number(token))
      fail("found the number " + printable_excerpt(token) + " where a keyword was expected (does a count disagree with the data?)");
    keyword_.clear();
    // Control bytes or megabytes without a space: not a keyword, and not to be echoed raw.
    if (printable_excerpt(token) != token)
      fail("found '" + printable_excerpt(token) + "' where a keyword was expected (not a Gamma mesh?)");
    keyword_ = std::string(token);
    keyword_code_ = gamma::keyword_code(token);
    if (keyword_code_ == kEnd) return false;
    if (keyword_code_ == kMeshVersionFormatted) {
      set_version(*this, scanner_.next_integer(keyword_));
    } else if (keyword_code_ == kDimension) {
      set_dimension(*this, scanner_.next_integer(keyword_));
    } else {
      return true;
    }
  }
}

void TextKeywordReader::skip_keyword(bool warn) {
  if (warn) warn_skipped();
  // The data of a keyword is numbers (and quoted strings, e.g. Identifier, Geometry); the first
  // other token is the next keyword.
  while (true) {
    std::string_view token = scanner_.next_token();
    if (token.empty()) return;
    if (token.front() == '"') {
      while (token.size() < 2 || token.back() != '"') {
        token = scanner_.next_token();
        if (token.empty()) fail("unterminated string");
      }
    } else if (!is_number(token)) {
      pending_ = token;
      return;
    }
  }
}

void TextKeywordReader::skip_records(Index count, int integers, int reals) {
  const std::int64_t tokens = static_cast<std::int64_t>(count) * (integers + reals);
  for (std::int64_t i = 0; i < tokens; ++i) scanner_.next_real(keyword_);
}

Index TextKeywordReader::read_count() {
  std::int64_t count = scanner_.next_integer(keyword_);
  if (count < 0) fail("negative count " + std::to_string(count));
  if (count > std::numeric_limits<Index>::max()) fail("count " + std::to_string(count) + " is too large for 32-bit indices");
  return static_cast<Index>(count);
}

int TextKeywordReader::read_header_integer() {
  std::int64_t value = scanner_.next_integer(keyword_);
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    fail("header value " + std::to_string(value) + " out of range");
  return static_cast<int>(value);
}

void TextKeywordReader::fail(std::string_view what, Index entity) const {
  std::string message = path_ + ": " + (keyword_.empty() ? "" : keyword_ + ": ") + std::string(what);
  if (entity != kNoIndex) message += ", entity " + one_based(entity);
  throw Error(message + ", line " + std::to_string(scanner_.line()));
}

// ---- binary ----

BinaryKeywordReader::BinaryKeywordReader(const std::string& path) : KeywordReaderState(path) {
  in_.open(path, std::ios::binary);
  if (!in_) throw Error(path + ": cannot open for reading");
  in_.seekg(0, std::ios::end);
  file_size_ = static_cast<std::uint64_t>(in_.tellg());
  in_.seekg(0);
  block_end_ = file_size_;
  std::int32_t code = read_word<std::int32_t>();
  if (code == kSwappedEndianCode)
    swap_bytes_ = true;
  else if (code != kNativeEndianCode)
    fail("not a Gamma binary file (endianness code " + std::to_string(code) + ")");
  set_version(*this, read_word<std::int32_t>());
  next_block_ = position();
}

bool BinaryKeywordReader::next_keyword() {
  while (true) {
    // A file cut at a block boundary still chains correctly: only its End keyword tells it is whole.
    if (next_block_ == 0 || next_block_ == file_size_) {
      keyword_.clear();
      fail("truncated file: it stops before its End keyword (byte " + std::to_string(file_size_) + ")");
    }
    std::uint64_t start = next_block_;
    seek(start);
    block_end_ = file_size_;
    keyword_ = "keyword at byte " + std::to_string(start);
    keyword_code_ = read_word<std::int32_t>();
    keyword_ = keyword_name(keyword_code_);
    std::int64_t next = read_position();
    if (next != 0 && (next < static_cast<std::int64_t>(position()) || static_cast<std::uint64_t>(next) > file_size_))
      fail("NextPos " + std::to_string(next) +
           (next < static_cast<std::int64_t>(position()) ? " points backward" : " points past the end of the file"));
    next_block_ = static_cast<std::uint64_t>(next);
    block_end_ = next != 0 ? next_block_ : file_size_;
    if (keyword_code_ == kEnd) return false;
    if (keyword_code_ == kDimension) {
      set_dimension(*this, read_word<std::int32_t>());
    } else {
      return true;
    }
  }
}

void BinaryKeywordReader::skip_keyword(bool warn) {
  if (warn) warn_skipped();  // next_keyword() jumps to NextPos
}

Index BinaryKeywordReader::read_count() {
  std::int64_t count = version_ >= 4 ? read_word<std::int64_t>() : read_word<std::int32_t>();
  if (count < 0) fail("negative count " + std::to_string(count));
  if (count > std::numeric_limits<Index>::max()) fail("count " + std::to_string(count) + " is too large for 32-bit indices");
  return static_cast<Index>(count);
}

int BinaryKeywordReader::read_header_integer() { return read_word<std::int32_t>(); }

void BinaryKeywordReader::expect_records(Index count, int integers, int reals) {
  const std::uint64_t bytes = record_bytes(integers, reals);
  std::uint64_t available = block_end_ - position();
  if (bytes * static_cast<std::uint64_t>(count) > available)
    fail(block_end_ == file_size_ ? "truncated file" : "data runs past the next keyword (NextPos)", static_cast<Index>(available / bytes));
}

void BinaryKeywordReader::skip_records(Index count, int integers, int reals) {
  expect_records(count, integers, reals);
  seek(position() + record_bytes(integers, reals) * static_cast<std::uint64_t>(count));
}

void BinaryKeywordReader::fail(std::string_view what, Index entity) const {
  std::string message = path_ + ": " + (keyword_.empty() ? "" : keyword_ + ": ") + std::string(what);
  if (entity != kNoIndex) message += ", entity " + one_based(entity);
  throw Error(message);
}

void BinaryKeywordReader::seek(std::uint64_t target) {
  if (target >= buffer_offset_ && target <= buffer_offset_ + filled_) {
    cursor_ = static_cast<std::size_t>(target - buffer_offset_);
    return;
  }
  in_.clear();
  in_.seekg(static_cast<std::streamoff>(target));
  buffer_offset_ = target;
  cursor_ = filled_ = 0;
}

const char* BinaryKeywordReader::refill(std::size_t bytes) {
  if (position() + bytes > block_end_) fail(block_end_ == file_size_ ? "truncated file" : "data runs past the next keyword (NextPos)");
  std::size_t unread = filled_ - cursor_;
  if (buffer_.size() < std::max(bytes, kReadChunkBytes)) buffer_.resize(std::max(bytes, kReadChunkBytes));
  std::copy(buffer_.begin() + static_cast<std::ptrdiff_t>(cursor_), buffer_.begin() + static_cast<std::ptrdiff_t>(filled_),
            buffer_.begin());
  buffer_offset_ += cursor_;
  cursor_ = 0;
  in_.clear();
  in_.read(buffer_.data() + unread, static_cast<std::streamsize>(buffer_.size() - unread));
  filled_ = unread + static_cast<std::size_t>(in_.gcount());
  if (filled_ < bytes) fail("read error");
  cursor_ = bytes;
  return buffer_.data();
}

}  // namespace hocav::gamma
