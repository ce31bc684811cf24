#include "derivations/syntax/document.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace dc {
namespace {

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Positions of offsets in one text: a table of line starts, so a lookup is O(log lines).
class Lines {
 public:
  Lines(const std::string& text, std::string file) : file_(std::move(file)) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts_.push_back(i + 1);
  }
  SourcePos at(std::size_t offset) const {
    auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
    const std::size_t line = static_cast<std::size_t>(it - starts_.begin());   // 1-based
    return {file_, static_cast<int>(line), static_cast<int>(offset - starts_[line - 1]) + 1};
  }

 private:
  std::string file_;
  std::vector<std::size_t> starts_;
};

// Environments whose content is displayed math, each row a step.
constexpr std::array<std::string_view, 7> kDisplayEnvs = {"equation", "align", "gather", "multline",
                                                         "eqnarray", "displaymath", "flalign"};
// Environments inside a display that only arrange rows: unwrapped.
constexpr std::array<std::string_view, 5> kInnerEnvs = {"split", "aligned", "gathered", "alignedat",
                                                        "multlined"};
// Environments whose text is not math or not prose.
constexpr std::array<std::string_view, 5> kSkipEnvs = {"verbatim", "lstlisting", "comment", "minted",
                                                       "Verbatim"};

std::string_view base_env(std::string_view env) {
  if (!env.empty() && env.back() == '*') env.remove_suffix(1);
  return env;
}
template <std::size_t N>
bool in(const std::array<std::string_view, N>& set, std::string_view env) {
  return std::find(set.begin(), set.end(), base_env(env)) != set.end();
}

// The name of \begin{NAME} at text[i] (text[i] == '\\'), or "" with end unchanged.
std::string env_name_at(const std::string& t, std::size_t i, std::string_view command, std::size_t* end) {
  if (t.compare(i, command.size(), command) != 0) return "";
  std::size_t p = i + command.size();
  while (p < t.size() && t[p] == ' ') ++p;
  if (p >= t.size() || t[p] != '{') return "";
  const std::size_t close = t.find('}', p);
  if (close == std::string::npos) return "";
  if (end) *end = close + 1;
  return t.substr(p + 1, close - p - 1);
}

class Splitter {
 public:
  explicit Splitter(SourceText source) : lines_(source.text, source.name) {
    doc_.source = std::move(source);
    doc_.kind = lower(doc_.source.name).find(".tex") != std::string::npos ||
                        ends_with(lower(doc_.source.name), ".ltx")
                    ? Document::Kind::Latex
                    : Document::Kind::Markdown;
    t_ = doc_.source.text;
  }

  Document run() {
    if (doc_.kind == Document::Kind::Latex) {
      blank_tex_comments();
      doc_.macro_text = t_;
      std::size_t body = t_.find("\\begin{document}");
      scan(body == std::string::npos ? 0 : body + 16);
    } else {
      front_matter();
      blank_markdown_code_and_comments();
      doc_.macro_text = t_;
      scan(0);
    }
    return std::move(doc_);
  }

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& message) {
    SourcePos p = lines_.at(at);
    throw InputError(p, message, 1, doc_.source.line(p.line));
  }

  // An opening delimiter without its closing one: reported, and read as text from here on.
  void unclosed(std::size_t at, const std::string& message) {
    const SourcePos p = lines_.at(at);
    doc_.warnings.push_back(InputError::warning(p, message + "; the text from here is read as prose", 1,
                                                doc_.source.line(p.line)));
  }

  void directive(std::size_t from, std::size_t to, bool rule_ok = true) {
    std::size_t p = from;
    while (p < to && std::isspace(static_cast<unsigned char>(t_[p]))) ++p;
    static constexpr std::string_view kWord = "derivcheck:";
    const bool addressed = t_.compare(p, kWord.size(), kWord) == 0;
    if (addressed) {
      p += kWord.size();
      while (p < to && t_[p] == ' ') ++p;
    }
    std::size_t e = to;
    while (e > p && std::isspace(static_cast<unsigned char>(t_[e - 1]))) --e;
    if (rule_ok && e > p + 3 && t_.compare(p, 3, "by ") == 0) {
      std::size_t q = p + 3;
      while (q < e && t_[q] == ' ') ++q;
      doc_.rule_comments.push_back({t_.substr(q, e - q), lines_.at(q), addressed});
      return;
    }
    if (addressed) doc_.directives.push_back({t_.substr(p, e - p), lines_.at(p)});
  }

  void blank(std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to && i < t_.size(); ++i)
      if (t_[i] != '\n') t_[i] = ' ';
  }

  // % to the end of the line (not \%); a `% derivcheck: …` comment is a directive.
  void blank_tex_comments() {
    for (std::size_t i = 0; i < t_.size(); ++i) {
      if (t_[i] == '\\') {
        ++i;
        continue;
      }
      if (t_[i] != '%') continue;
      std::size_t e = t_.find('\n', i);
      if (e == std::string::npos) e = t_.size();
      directive(i + 1, e);
      blank(i, e);
      i = e;
    }
  }

  void front_matter() {
    if (t_.rfind("---\n", 0) != 0 && t_.rfind("---\r\n", 0) != 0) return;
    std::size_t p = t_.find('\n') + 1;
    while (p < t_.size()) {
      std::size_t e = t_.find('\n', p);
      if (e == std::string::npos) e = t_.size();
      std::string_view line(t_.data() + p, e - p);
      if (line == "---" || line == "---\r" || line == "..." ) {
        blank(0, e);
        return;
      }
      directive(p, e, false);
      p = e + 1;
    }
  }

  // Fenced code (``` or ~~~), inline code spans and HTML comments hold no math.
  void blank_markdown_code_and_comments() {
    std::size_t p = 0;
    bool fence = false;
    std::string fence_mark;
    while (p < t_.size()) {
      std::size_t e = t_.find('\n', p);
      if (e == std::string::npos) e = t_.size();
      std::size_t q = p;
      while (q < e && q - p < 4 && t_[q] == ' ') ++q;
      const bool is_fence = t_.compare(q, 3, "```") == 0 || t_.compare(q, 3, "~~~") == 0;
      if (fence) {
        if (is_fence && t_.compare(q, 3, fence_mark) == 0) fence = false;
        blank(p, e);
      } else if (is_fence) {
        fence = true;
        fence_mark = t_.substr(q, 3);
        blank(p, e);
      }
      p = e + 1;
    }
    for (std::size_t i = 0; i < t_.size(); ++i) {
      if (t_.compare(i, 4, "<!--") == 0) {
        std::size_t e = t_.find("-->", i + 4);
        if (e == std::string::npos) fail(i, "unclosed HTML comment '<!--'");
        directive(i + 4, e);
        blank(i, e + 3);
        i = e + 2;
      } else if (t_[i] == '\\') {
        ++i;
      } else if (t_[i] == '`') {
        std::size_t n = 0;
        while (i + n < t_.size() && t_[i + n] == '`') ++n;
        const std::string ticks(n, '`');
        std::size_t e = t_.find(ticks, i + n);
        const std::size_t para = t_.find("\n\n", i + n);
        if (e == std::string::npos || (para != std::string::npos && para < e)) {
          i += n - 1;
          continue;
        }
        blank(i, e + n);
        i = e + n - 1;
      }
    }
  }

  bool blank_line_at(std::size_t i) const {
    // t_[i] == '\n' and the next line holds only spaces
    std::size_t p = i + 1;
    while (p < t_.size() && (t_[p] == ' ' || t_[p] == '\t' || t_[p] == '\r')) ++p;
    return p >= t_.size() || t_[p] == '\n';
  }

  void new_paragraph() {
    ++paragraph_;
  }

  void prose(char c) {
    if (prose_.size() < 4000) prose_ += c;
  }

  void scan(std::size_t from) {
    const bool latex = doc_.kind == Document::Kind::Latex;
    bool line_start = true;
    for (std::size_t i = from; i < t_.size(); ++i) {
      const char c = t_[i];
      if (c == '\n') {
        if (blank_line_at(i)) new_paragraph();
        prose(' ');
        line_start = true;
        continue;
      }
      if (!latex && line_start && (c == '#' || numbered_heading_at(i))) {
        ++section_;
        new_paragraph();
      }
      if (c != ' ' && c != '\t') line_start = false;
      if (c == '\\' && i + 1 < t_.size()) {
        std::size_t end = 0;
        std::string env = env_name_at(t_, i, "\\begin", &end);
        if (!env.empty() && in(kDisplayEnvs, env)) {
          const std::string close = "\\end{" + env + "}";
          const std::size_t e = t_.find(close, end);
          if (e == std::string::npos) {
            unclosed(i, "'\\begin{" + env + "}' is not closed by '" + close + "'");
            continue;
          }
          display(i, end, e, env, e + close.size());
          i = e + close.size() - 1;
          continue;
        }
        if (!env.empty() && in(kSkipEnvs, env)) {
          const std::string close = "\\end{" + env + "}";
          const std::size_t e = t_.find(close, end);
          if (e == std::string::npos) {
            unclosed(i, "'\\begin{" + env + "}' is not closed by '" + close + "'");
            continue;
          }
          i = e + close.size() - 1;
          continue;
        }
        if (t_[i + 1] == '[') {
          const std::size_t e = t_.find("\\]", i + 2);
          if (e == std::string::npos) {
            unclosed(i, "'\\[' is not closed by '\\]'");
            ++i;
            continue;
          }
          display(i, i + 2, e, "\\[", e + 2);
          i = e + 1;
          continue;
        }
        if (t_[i + 1] == '(') {
          const std::size_t e = t_.find("\\)", i + 2);
          if (e == std::string::npos) {
            unclosed(i, "'\\(' is not closed by '\\)'");
            ++i;
            continue;
          }
          inline_math(i + 2, e);
          i = e + 1;
          continue;
        }
        if (latex && is_sectioning(i)) {
          ++section_;
          new_paragraph();
        }
        prose(c);
        prose(t_[i + 1]);
        ++i;
        continue;
      }
      if (c == '$') {
        if (i + 1 < t_.size() && t_[i + 1] == '$') {
          const std::size_t e = t_.find("$$", i + 2);
          if (e == std::string::npos) {
            unclosed(i, "'$$' is not closed by '$$'");
            ++i;
            continue;
          }
          display(i, i + 2, e, "$$", e + 2);
          i = e + 1;
          continue;
        }
        const std::size_t e = inline_close(i);
        if (e == std::string::npos) {
          if (latex) unclosed(i, "'$' is not closed by '$'");
          prose(c);
          continue;
        }
        inline_math(i + 1, e);
        i = e;
        continue;
      }
      prose(c);
    }
  }

  // A Markdown line that is a numbered heading written as plain text (`9.4 Variable Mass
  // System`, as documents converted from PDF have them): a paragraph of one short line that
  // starts with a section number of two or more parts and a capitalised word, with no math.
  bool numbered_heading_at(std::size_t i) const {
    if (i > 0 && !(i >= 2 && t_[i - 1] == '\n' && t_[i - 2] == '\n')) return false;
    std::size_t p = i, parts = 0;
    while (true) {
      const std::size_t d = p;
      while (p < t_.size() && std::isdigit(static_cast<unsigned char>(t_[p]))) ++p;
      if (p == d) return false;
      ++parts;
      if (p < t_.size() && t_[p] == '.' && p + 1 < t_.size() && std::isdigit(static_cast<unsigned char>(t_[p + 1]))) {
        ++p;
        continue;
      }
      break;
    }
    if (parts < 2 || p + 1 >= t_.size() || t_[p] != ' ' || !std::isupper(static_cast<unsigned char>(t_[p + 1])))
      return false;
    const std::size_t end = t_.find('\n', p);
    const std::size_t stop = end == std::string::npos ? t_.size() : end;
    if (stop - i > 100 || t_.find('$', p) < stop) return false;
    return stop >= t_.size() || (stop + 1 < t_.size() && t_[stop + 1] == '\n') || stop + 1 == t_.size();
  }

  bool is_sectioning(std::size_t i) const {
    for (std::string_view cmd : {"\\part", "\\chapter", "\\section", "\\subsection", "\\subsubsection",
                                 "\\paragraph"}) {
      if (t_.compare(i, cmd.size(), cmd) != 0) continue;
      const std::size_t p = i + cmd.size();
      if (p < t_.size() && (t_[p] == '{' || t_[p] == '*' || t_[p] == ' ' || t_[p] == '[')) return true;
    }
    return false;
  }

  // The closing '$' of inline math opened at i. Markdown follows pandoc: the opening '$' has a
  // non-space right after it, the closing one a non-space right before it and no digit after
  // it, both in one paragraph. LaTeX: the next unescaped '$'.
  std::size_t inline_close(std::size_t i) const {
    const bool latex = doc_.kind == Document::Kind::Latex;
    if (!latex && (i + 1 >= t_.size() || std::isspace(static_cast<unsigned char>(t_[i + 1]))))
      return std::string::npos;
    for (std::size_t p = i + 1; p < t_.size(); ++p) {
      if (t_[p] == '\\') {
        ++p;
        continue;
      }
      if (t_[p] == '\n' && !latex && blank_line_at(p)) return std::string::npos;
      if (t_[p] != '$') continue;
      if (latex) return p;
      if (std::isspace(static_cast<unsigned char>(t_[p - 1]))) continue;
      if (p + 1 < t_.size() && std::isdigit(static_cast<unsigned char>(t_[p + 1]))) continue;
      return p;
    }
    return std::string::npos;
  }

  void inline_math(std::size_t from, std::size_t to) {
    DocInline m;
    m.text = t_.substr(from, to - from);
    m.origin = lines_.at(from);
    m.section = section_;
    m.paragraph = paragraph_;
    m.displays_before = doc_.displays.size();
    // the prose keeps the math too: "substitute $v_2 \approx v_0$" names an approximation
    prose(' ');
    for (char c : m.text) prose(c == '\n' ? ' ' : c);
    prose(' ');
    doc_.inlines.push_back(std::move(m));
  }

  // The rows of a display whose content is t_[from, to).
  void display(std::size_t at, std::size_t from, std::size_t to, const std::string& env, std::size_t end) {
    DocDisplay d;
    d.pos = lines_.at(at);
    d.end = end;
    d.env = env;
    d.section = section_;
    d.paragraph = paragraph_;
    d.prose_before = prose_;
    prose_.clear();
    std::string body = t_.substr(from, to - from);
    unwrap_inner(body);
    std::size_t row_start = 0;
    int depth = 0, env_depth = 0;
    auto emit = [&](std::size_t b, std::size_t e) {
      while (b < e && std::isspace(static_cast<unsigned char>(body[b]))) ++b;
      while (e > b && std::isspace(static_cast<unsigned char>(body[e - 1]))) --e;
      if (b == e) return;
      d.rows.push_back({body.substr(b, e - b), lines_.at(from + b)});
    };
    for (std::size_t i = 0; i < body.size(); ++i) {
      const char c = body[i];
      if (c == '{') ++depth;
      else if (c == '}') --depth;
      else if (c == '\\' && i + 1 < body.size()) {
        if (body.compare(i, 7, "\\begin{") == 0) ++env_depth;
        else if (body.compare(i, 5, "\\end{") == 0) --env_depth;
        else if (body[i + 1] == '\\' && depth == 0 && env_depth == 0) {
          emit(row_start, i);
          std::size_t p = i + 2;
          if (p < body.size() && body[p] == '*') ++p;
          while (p < body.size() && std::isspace(static_cast<unsigned char>(body[p]))) ++p;
          if (p < body.size() && body[p] == '[') {
            const std::size_t close = body.find(']', p);
            if (close != std::string::npos) p = close + 1;
          }
          row_start = p;
          i = p - 1;
          continue;
        }
        ++i;
      }
    }
    emit(row_start, body.size());
    doc_.displays.push_back(std::move(d));
  }

  // \begin{split} … \end{split} (and aligned, gathered, …) only arrange rows: blanked, so the
  // rows inside split at \\ like the display's own.
  static void unwrap_inner(std::string& body) {
    for (std::size_t i = 0; i < body.size(); ++i) {
      if (body[i] != '\\') continue;
      std::size_t end = 0;
      std::string env = env_name_at(body, i, "\\begin", &end);
      if (env.empty()) env = env_name_at(body, i, "\\end", &end);
      if (env.empty() || !in(kInnerEnvs, env)) continue;
      // \begin{alignedat}{2}: the column count too
      if (base_env(env) == "alignedat" && end < body.size() && body[end] == '{') {
        const std::size_t close = body.find('}', end);
        if (close != std::string::npos) end = close + 1;
      }
      // \begin{aligned}[t]
      if (end < body.size() && body[end] == '[') {
        const std::size_t close = body.find(']', end);
        if (close != std::string::npos) end = close + 1;
      }
      for (std::size_t k = i; k < end; ++k)
        if (body[k] != '\n') body[k] = ' ';
      i = end - 1;
    }
  }

  Document doc_;
  Lines lines_;
  std::string t_;            // the text with comments and code blanked (offsets unchanged)
  std::string prose_;
  int section_ = 0;
  int paragraph_ = 0;
};

}  // namespace

bool is_document_path(std::string_view path) {
  const std::string p = lower(path);
  return ends_with(p, ".tex") || ends_with(p, ".ltx") || ends_with(p, ".md") || ends_with(p, ".markdown");
}

Document split_document(SourceText source) { return Splitter(std::move(source)).run(); }

}  // namespace dc
