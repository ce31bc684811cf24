// Source positions and input errors.
//
// Every user-facing input problem (malformed file, unknown symbol, impossible physics,
// runaway expression) is an InputError carrying a position; the CLI prints it GCC style
//   file:line:col: error: message
//       offending source line
//       ^~~~
// and exits with code 2. No GiNaC or C++ internals ever appear in the message.
#pragma once
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace dc {

// One line/column in one input (1-based; col counts bytes). file may be "<arg>" or "<stdin>".
struct SourcePos {
  std::string file;
  int line = 0;
  int col = 0;
};

// The position of text[offset] when text[0] is at `origin` (a newline starts the next line).
SourcePos position_in(std::string_view text, const SourcePos& origin, std::size_t offset);

// The text of an input, kept so errors can quote the offending line.
struct SourceText {
  std::string name;   // file name as the user gave it
  std::string text;   // whole content
  std::string line(int line_no) const;  // without the newline; empty if out of range
};

class InputError : public std::runtime_error {
 public:
  // length: how many characters to underline (>= 1).
  InputError(SourcePos pos, std::string message, int length = 1, std::string line_text = {});
  const SourcePos& pos() const { return pos_; }
  const std::string& message() const { return message_; }
  int length() const { return length_; }
  const std::string& line_text() const { return line_text_; }
  InputError with_line_text(std::string text) const;
  // A positioned message that stops nothing and does not change the exit code, reported beside
  // what it concerns: a warning (something is probably not what the author meant) or a note
  // (what the checker took a name to mean). "file:line:col: warning: message".
  enum class Severity { Error, Warning, Note };
  static InputError warning(SourcePos pos, std::string message, int length = 1, std::string line_text = {});
  static InputError note(SourcePos pos, std::string message, int length = 1, std::string line_text = {});
  Severity severity() const { return severity_; }
  const char* severity_word() const;
  // "file:line:col: error: message" plus, when line_text is known, the line and a caret.
  std::string format() const;

 private:
  SourcePos pos_;
  std::string message_;
  int length_;
  std::string line_text_;
  Severity severity_ = Severity::Error;
};

// A suggestion for a misspelt name: " (did you mean 'theta'?)" for the candidate nearest to
// `name` in edit distance (insertions, deletions, substitutions and swaps of neighbours), when
// that distance is at most 1 for names of up to 4 characters, 2 up to 8 and 3 beyond; the
// first such candidate in the given order on a tie; "" when none is that near (or `name` is
// itself a candidate).
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace dc
