// Keyword-by-keyword writers of Gamma/Medit files, ASCII and binary, with one interface so the mesh
// and solution writers lay out each keyword once (as templates over the writer):
//   begin_keyword(code, count, integers, reals, header)  opens a keyword of `count` records of
//       `integers` integers and `reals` reals each (in any order), after the header integers
//       (the solution type codes)
//   write_integer(v), write_real(v), end_record()
//   finish()  writes End and renames the temporary file into place; without it nothing appears.
//   position(), leave_records(bytes): where the records start, and a hole left for them (other
//       writers fill it in place: a distributed run's processes, each its records)
// ASCII reals are written in the shortest form that reads back to the same double. Binary NextPos
// values are computed from the announced sizes, so the output streams without seeking. The records
// themselves are encoded by TextRecords and BinaryRecords, which also encode them into memory.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "io/atomic_output.hpp"

namespace hocav::gamma {

// Records as a .mesh writes them (integers, then reals, separated by spaces, one record per line),
// appended to `bytes`.
struct TextRecords {
  std::string bytes;

  void write_integer(std::int64_t value);
  void write_real(double value);
  void end_record();
};

// Records as a .meshb of `version` (1-4) writes them, appended to `bytes`. Throws Error (naming
// `path`) for a value the version cannot hold.
class BinaryRecords {
 public:
  BinaryRecords(std::string path, int version) : path_(std::move(path)), version_(version) {}

  std::string bytes;

  void write_integer(std::int64_t value);
  void write_real(double value);
  void end_record() {}
  template <class Word>
  void put(Word value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  const std::string& path() const { return path_; }
  int version() const { return version_; }

 private:
  std::string path_;
  int version_;
};

class TextKeywordWriter {
 public:
  TextKeywordWriter(const std::string& path, int version, int dimension);

  void begin_keyword(int code, std::int64_t count, int integers, int reals, std::span<const int> header = {});
  void write_integer(std::int64_t value);
  void write_real(double value);
  void end_record();
  void finish();
  // The bytes written so far (the offset of the next).
  std::uint64_t position() const { return flushed_ + records_.bytes.size(); }
  // Leaves `bytes` unwritten, a hole for the open keyword's records.
  void leave_records(std::uint64_t bytes);

 private:
  void flush();

  AtomicOutput out_;
  TextRecords records_;
  std::uint64_t flushed_ = 0;
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
  std::uint64_t position() const { return flushed_ + records_.bytes.size(); }
  // Leaves the open keyword's records unwritten, a hole in the file for other writers to fill in
  // place (a distributed run's processes, each its records); `bytes` must be the announced size.
  void leave_records(std::uint64_t bytes);

 private:
  void put_position(std::uint64_t position);
  void check_block_complete() const;
  void flush();

  AtomicOutput out_;
  BinaryRecords records_;
  std::uint64_t flushed_ = 0;    // bytes written to the file so far
  std::uint64_t block_end_ = 0;  // the NextPos announced for the open block
};

// The version to write: `requested` (1-4), or for 0 `default_version` — 4 when integers beyond 32
// bits must be written. Throws Error for an unknown version or one that cannot hold the integers.
int resolve_version(const std::string& path, int requested, std::int64_t largest_integer, int default_version);

}  // namespace hocav::gamma
