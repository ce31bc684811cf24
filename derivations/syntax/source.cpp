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

namespace {
// Optimal string alignment distance (Damerau-Levenshtein without repeated edits of a substring).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}
}  // namespace

std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates) {
  const std::size_t limit = name.size() <= 4 ? 1 : name.size() <= 8 ? 2 : 3;
  const std::string* best = nullptr;
  std::size_t best_d = limit + 1;
  for (const auto& c : candidates) {
    if (c == name) return {};
    // far longer or shorter names cannot be near: skip the table
    if ((c.size() > name.size() ? c.size() - name.size() : name.size() - c.size()) > limit) continue;
    std::size_t dist = edit_distance(name, c);
    if (dist < best_d) {
      best_d = dist;
      best = &c;
    }
  }
  return best ? " (did you mean '" + *best + "'?)" : std::string();
}

}  // namespace dc
