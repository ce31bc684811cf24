#include "derivations/syntax/source.hpp"

#include <algorithm>

namespace dc {

namespace {
// "file:line:col" — or just "file" for errors about a whole file (line 0), as GCC does.
std::string where(const SourcePos& p) {
  if (p.line <= 0) return p.file;
  return p.file + ":" + std::to_string(p.line) + ":" + std::to_string(p.col);
}
}  // namespace

SourcePos position_in(std::string_view text, const SourcePos& origin, std::size_t offset) {
  SourcePos p = origin;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.col = 1;
    } else {
      ++p.col;
    }
  }
  return p;
}

std::string SourceText::line(int line_no) const {
  if (line_no < 1) return {};
  std::size_t start = 0;
  for (int l = 1; l < line_no; ++l) {
    std::size_t nl = text.find('\n', start);
    if (nl == std::string::npos) return {};
    start = nl + 1;
  }
  std::size_t end = text.find('\n', start);
  std::string s = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
  if (!s.empty() && s.back() == '\r') s.pop_back();
  return s;
}

InputError::InputError(SourcePos pos, std::string message, int length, std::string line_text)
    : std::runtime_error(where(pos) + ": error: " + message),
      pos_(std::move(pos)),
      message_(std::move(message)),
      length_(std::max(1, length)),
      line_text_(std::move(line_text)) {}

InputError InputError::with_line_text(std::string text) const {
  InputError e(pos_, message_, length_, std::move(text));
  e.severity_ = severity_;
  return e;
}

InputError InputError::warning(SourcePos pos, std::string message, int length, std::string line_text) {
  InputError e(std::move(pos), std::move(message), length, std::move(line_text));
  e.severity_ = Severity::Warning;
  return e;
}

InputError InputError::note(SourcePos pos, std::string message, int length, std::string line_text) {
  InputError e(std::move(pos), std::move(message), length, std::move(line_text));
  e.severity_ = Severity::Note;
  return e;
}

const char* InputError::severity_word() const {
  switch (severity_) {
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
    case Severity::Error: break;
  }
  return "error";
}

std::string InputError::format() const {
  std::string out = where(pos_) + ": " + severity_word() + ": " + message_ + "\n";
  if (!line_text_.empty() && pos_.col >= 1) {
    // Show at most 200 characters around the column so huge inputs stay readable.
    std::size_t col = static_cast<std::size_t>(pos_.col - 1);
    std::size_t from = col > 100 ? col - 100 : 0;
    std::string shown = line_text_.substr(from, 200);
    for (char& c : shown)
      if (c == '\t') c = ' ';
    out += "    " + shown + "\n";
    std::size_t caret = std::min(col - from, shown.size());
    // Columns count bytes; the caret line counts characters, so multi-byte UTF-8 characters
    // (μ, θ, ·) before the caret take one space each.
    std::size_t caret_chars = 0;
    for (std::size_t i = 0; i < caret; ++i)
      if ((static_cast<unsigned char>(shown[i]) & 0xC0) != 0x80) ++caret_chars;
    int len = std::max(1, std::min<int>(length_, static_cast<int>(shown.size() - std::min(caret, shown.size())) > 0
                                                      ? static_cast<int>(shown.size() - caret)
                                                      : 1));
    out += "    " + std::string(caret_chars, ' ') + "^" + std::string(static_cast<std::size_t>(len - 1), '~') + "\n";
  }
  return out;
}

}  // namespace dc
