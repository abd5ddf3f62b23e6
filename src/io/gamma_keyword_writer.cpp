#include "io/gamma_keyword_writer.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "base/error.hpp"
#include "io/gamma_keywords.hpp"

namespace hocav::gamma {
namespace {

constexpr std::size_t kFlushBytes = std::size_t{1} << 20;
constexpr std::int64_t kInt32Max = std::numeric_limits<std::int32_t>::max();

template <class Number>
void append_number(std::string& buffer, Number value) {
  char text[32];
  auto [end, error] = std::to_chars(text, text + sizeof text, value);
  if (error != std::errc()) throw std::logic_error("to_chars failed");
  buffer.append(text, end);
  buffer += ' ';
}

}  // namespace

int resolve_version(const std::string& path, int requested, std::int64_t largest_integer, int default_version) {
  if (requested == 0) return largest_integer > kInt32Max ? 4 : default_version;
  if (requested < 1 || requested > 4) throw Error(path + ": unknown Gamma version " + std::to_string(requested) + " (1 to 4 are known)");
  if (requested < 4 && largest_integer > kInt32Max)
    throw Error(path + ": Gamma version " + std::to_string(requested) + " cannot hold node number " + std::to_string(largest_integer) +
                " (use version 4)");
  return requested;
}

// ---- records ----

void TextRecords::write_integer(std::int64_t value) { append_number(bytes, value); }

void TextRecords::write_real(double value) { append_number(bytes, value); }

void TextRecords::end_record() {
  if (!bytes.empty() && bytes.back() == ' ') bytes.back() = '\n';
}

void BinaryRecords::write_integer(std::int64_t value) {
  if (version_ >= 4) return put<std::int64_t>(value);
  if (value > kInt32Max || value < std::numeric_limits<std::int32_t>::min())
    throw Error(path_ + ": integer " + std::to_string(value) + " does not fit Gamma version " + std::to_string(version_));
  put<std::int32_t>(static_cast<std::int32_t>(value));
}

void BinaryRecords::write_real(double value) {
  if (version_ >= 2) return put<double>(value);
  auto single = static_cast<float>(value);
  if (!std::isfinite(single)) throw Error(path_ + ": value " + std::to_string(value) + " exceeds the 32-bit reals of Gamma version 1");
  put<float>(single);
}

// ---- ASCII ----

TextKeywordWriter::TextKeywordWriter(const std::string& path, int version, int dimension) : out_(path) {
  // Appended piece by piece: GCC 12 sees a false -Wrestrict in chains of string operator+.
  std::string& text = records_.bytes;
  text += keyword_name(kMeshVersionFormatted);
  text += ' ';
  append_number(text, version);
  end_record();
  text += '\n';
  text += keyword_name(kDimension);
  text += ' ';
  append_number(text, dimension);
  end_record();
}

void TextKeywordWriter::begin_keyword(int code, std::int64_t count, int, int, std::span<const int> header) {
  std::string& text = records_.bytes;
  text += '\n';
  text += keyword_name(code);
  text += '\n';
  append_number(text, count);
  end_record();
  if (header.empty()) return;
  for (int value : header) append_number(text, value);
  end_record();
}

void TextKeywordWriter::write_integer(std::int64_t value) { records_.write_integer(value); }

void TextKeywordWriter::write_real(double value) { records_.write_real(value); }

void TextKeywordWriter::end_record() {
  records_.end_record();
  if (records_.bytes.size() >= kFlushBytes) flush();
}

void TextKeywordWriter::finish() {
  records_.bytes += '\n';
  records_.bytes += keyword_name(kEnd);
  records_.bytes += '\n';
  flush();
  out_.commit();
}

void TextKeywordWriter::leave_records(std::uint64_t bytes) {
  flush();
  flushed_ += bytes;
  out_.stream().seekp(static_cast<std::streamoff>(flushed_));
}

void TextKeywordWriter::flush() {
  out_.stream().write(records_.bytes.data(), static_cast<std::streamsize>(records_.bytes.size()));
  flushed_ += records_.bytes.size();
  records_.bytes.clear();
}

// ---- binary ----

BinaryKeywordWriter::BinaryKeywordWriter(const std::string& path, int version, int dimension) : out_(path), records_(path, version) {
  records_.put<std::int32_t>(1);  // endianness code
  records_.put<std::int32_t>(version);
  records_.put<std::int32_t>(kDimension);
  block_end_ = position() + (version >= 3 ? 8 : 4) + 4;
  put_position(block_end_);
  records_.put<std::int32_t>(dimension);
}

void BinaryKeywordWriter::begin_keyword(int code, std::int64_t count, int integers, int reals, std::span<const int> header) {
  check_block_complete();
  const int version = records_.version();
  const std::uint64_t record_bytes = static_cast<std::uint64_t>(integers) * (version >= 4 ? 8 : 4) +
                                     static_cast<std::uint64_t>(reals) * (version == 1 ? 4 : 8);
  const std::uint64_t header_bytes = 4 + (version >= 3 ? 8 : 4) + (version >= 4 ? 8 : 4) + 4 * header.size();
  block_end_ = position() + header_bytes + record_bytes * static_cast<std::uint64_t>(count);
  if (version <= 2 && block_end_ > static_cast<std::uint64_t>(kInt32Max))
    throw Error(records_.path() + ": " + keyword_name(code) + ": the file outgrows the 2 GiB reach of Gamma version " +
                std::to_string(version) + " (use version 3)");
  records_.put<std::int32_t>(code);
  put_position(block_end_);
  if (version >= 4)
    records_.put<std::int64_t>(count);
  else
    records_.put<std::int32_t>(static_cast<std::int32_t>(count));
  for (int value : header) records_.put<std::int32_t>(value);  // solution type codes stay 32-bit in every version
}

void BinaryKeywordWriter::write_integer(std::int64_t value) { records_.write_integer(value); }

void BinaryKeywordWriter::write_real(double value) { records_.write_real(value); }

void BinaryKeywordWriter::end_record() {
  if (records_.bytes.size() >= kFlushBytes) flush();
}

void BinaryKeywordWriter::finish() {
  check_block_complete();
  records_.put<std::int32_t>(kEnd);
  put_position(0);
  flush();
  out_.commit();
}

void BinaryKeywordWriter::leave_records(std::uint64_t bytes) {
  if (position() + bytes != block_end_) throw std::logic_error("Gamma binary hole of a size other than announced");
  flush();
  flushed_ = block_end_;
  out_.stream().seekp(static_cast<std::streamoff>(block_end_));
}

void BinaryKeywordWriter::put_position(std::uint64_t position) {
  if (records_.version() >= 3)
    records_.put<std::int64_t>(static_cast<std::int64_t>(position));
  else
    records_.put<std::int32_t>(static_cast<std::int32_t>(position));
}

void BinaryKeywordWriter::check_block_complete() const {
  if (position() != block_end_) throw std::logic_error("Gamma binary block written with a size other than announced");
}

void BinaryKeywordWriter::flush() {
  out_.stream().write(records_.bytes.data(), static_cast<std::streamsize>(records_.bytes.size()));
  flushed_ += records_.bytes.size();
  records_.bytes.clear();
}

}  // namespace hocav::gamma
