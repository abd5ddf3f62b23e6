// Whitespace-separated token scanner over a whole text file, tracking line numbers so readers can
// say where input went wrong. Shared by the ASCII readers (.mesh, .sol, .msh).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace hocav {

class TextScanner {
 public:
  // Reads the whole file. Throws Error "<path>: cannot open" when it cannot.
  explicit TextScanner(std::string path, char comment_char = '\0');
  // Scans text already in memory (for tests and fuzzing); `path` names it in messages.
  TextScanner(std::string path, std::string text, char comment_char);

  // The next token, or an empty view at the end of the file.
  std::string_view next_token();
  bool at_end();
  // The line of the last token returned (1-based).
  std::size_t line() const { return token_line_; }
  const std::string& path() const { return path_; }

  // Typed reads; `what` names the thing read (e.g. "Vertices") in the error message. Throws Error
  // on end of file, malformed numbers, overflow, and (reals) NaN or infinity.
  std::int64_t next_integer(std::string_view what);
  double next_real(std::string_view what);

  // Throws Error "<path>: <what>: <message>, line N".
  [[noreturn]] void fail(std::string_view what, std::string_view message) const;

 private:
  void skip_space_and_comments();

  std::string path_;
  std::string text_;
  std::size_t position_ = 0;
  std::size_t current_line_ = 1;
  std::size_t token_line_ = 1;
  char comment_char_;
};

}  // namespace hocav
