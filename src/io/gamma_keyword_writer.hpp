// Keyword-by-keyword writers of Gamma/Medit files, ASCII and binary, with one interface so the mesh
// and solution writers lay out each keyword once (as templates over the writer):
//   begin_keyword(code, count, integers, reals, header)  opens a keyword of `count` records of
//       `integers` integers and `reals` reals each (in any order), after the header integers
//       (the solution type codes)
//   write_integer(v), write_real(v), end_record()
//   finish()  writes End and renames the temporary file into place; without it nothing appears.
//   (binary only) position(), leave_records(): where the records start, and a hole left for them
// ASCII reals are written in the shortest form that reads back to the same double. Binary NextPos
// values are computed from the announced sizes, so the output streams without seeking.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "io/atomic_output.hpp"

namespace hocav::gamma {

class TextKeywordWriter {
 public:
  TextKeywordWriter(const std::string& path, int version, int dimension);

  void begin_keyword(int code, std::int64_t count, int integers, int reals, std::span<const int> header = {});
  void write_integer(std::int64_t value);
  void write_real(double value);
  void end_record();
  void finish();

 private:
  void flush();

  AtomicOutput out_;
  std::string buffer_;
};

class BinaryKeywordWriter {
 public:
  // `version` 1-4, e.g. from resolve_version().
  BinaryKeywordWriter(const std::string& path, int version, int dimension);

  void begin_keyword(int code, std::int64_t count, int integers, int reals, std::span<const int> header = {});
  void write_integer(std::int64_t value);
  void write_real(double value);
  void end_record();
  void finish();
  // The bytes written so far (the offset of the next).
  std::uint64_t position() const { return offset_; }
  // Leaves the open keyword's records unwritten, a hole in the file for other writers to fill in
  // place (a distributed run's processes, each its rows).
  void leave_records();

 private:
  template <class Word>
  void put(Word value) {
    buffer_.append(reinterpret_cast<const char*>(&value), sizeof value);
    offset_ += sizeof value;
  }
  void put_position(std::uint64_t position);
  void check_block_complete() const;
  void flush();

  AtomicOutput out_;
  std::string path_;
  int version_;
  std::string buffer_;
  std::uint64_t offset_ = 0;     // bytes written so far, buffered ones included
  std::uint64_t block_end_ = 0;  // the NextPos announced for the open block
};

// The version to write: `requested` (1-4), or for 0 `default_version` — 4 when integers beyond 32
// bits must be written. Throws Error for an unknown version or one that cannot hold the integers.
int resolve_version(const std::string& path, int requested, std::int64_t largest_integer, int default_version);

}  // namespace hocav::gamma
