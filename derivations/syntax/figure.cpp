// The words after a figure's caption (see figure.hpp).
#include "derivations/syntax/figure.hpp"

#include <algorithm>
#include <stdexcept>

namespace dc {

namespace {

bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9') || c == '_'; }
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

class SpecParser {
 public:
  SpecParser(const ProseSource& src, const std::function<void(const SourcePos&, const std::string&, int)>& fail)
      : t_(src.text), src_(src), fail_(fail) {}

  FigureSpec run() {
    FigureSpec f;
    skip();
    if (p_ >= t_.size()) return f;
    f.pos = at(p_);
    const std::size_t kw_at = p_;
    const std::string kw = word();
    if (kw == "simulate") {
      f.kind = FigureSpec::Kind::Scene;
      f.scene = name("a scene name after 'simulate' (derivcheck simulate --list names them)");
      skip();
      if (p_ < t_.size()) {
        expect_word("with", "'with NAME = VALUE, ...' or the end of the figure line after the scene");
        f.with = assignments(t_.size());
      }
      return f;
    }
    if (kw != "plot") {
      fail(at(kw_at), "expected 'simulate SCENE' or 'plot LABEL over X = LO .. HI' after the figure's caption",
           static_cast<int>(std::max<std::size_t>(1, kw.size())));
    }
    f.kind = FigureSpec::Kind::Plot;
    f.curves.push_back(name("the label of a step 'y = expression' after 'plot'"));
    for (skip(); p_ < t_.size() && t_[p_] == ','; skip()) {
      ++p_;
      f.curves.push_back(name("the label of a step 'y = expression' after ','"));
    }
    expect_word("over", "'over X = LO .. HI' after the labels of the plotted steps");
    f.var = name("the symbol along the horizontal axis after 'over'");
    skip();
    if (p_ >= t_.size() || t_[p_] != '=') fail(at(p_), "expected '=' and the range 'LO .. HI' after '" + f.var.name + "'");
    ++p_;
    // the range runs to the word `with` (outside parentheses) or to the end
    const std::size_t b = p_, e = find_with(p_);
    const std::size_t dots = t_.find("..", b);
    if (dots == std::string::npos || dots >= e)
      fail(at(nonblank(b, e)), "expected a range 'LO .. HI' after '" + f.var.name + " ='", 1);
    f.range_pos = at(nonblank(b, dots));
    f.lo = expression(b, dots, "the lower end of the range before '..'");
    f.hi = expression(dots + 2, e, "the upper end of the range after '..'");
    std::size_t last = e;
    while (last > b && blank(t_[last - 1])) --last;
    if (at(nonblank(b, dots)).line == at(last - 1).line)
      f.range_length = std::max(1, at(last - 1).col - f.range_pos.col + 1);
    p_ = e;
    skip();
    if (p_ < t_.size()) {
      expect_word("with", "'with NAME = VALUE, ...' or the end of the figure line after the range");
      f.with = assignments(t_.size());
    }
    return f;
  }

 private:
  const std::string& t_;
  const ProseSource& src_;
  const std::function<void(const SourcePos&, const std::string&, int)>& fail_;
  std::size_t p_ = 0;

  SourcePos at(std::size_t i) const { return i < src_.pos.size() ? src_.pos[i] : src_.end; }
  [[noreturn]] void fail(const SourcePos& p, const std::string& msg, int len = 1) const {
    fail_(p, msg, len);
    throw std::logic_error("figure: fail returned");   // fail_ never returns
  }
  void skip() {
    while (p_ < t_.size() && blank(t_[p_])) ++p_;
  }
  std::size_t nonblank(std::size_t b, std::size_t e) const {
    while (b < e && blank(t_[b])) ++b;
    return b;
  }
  std::string word() {
    std::size_t b = p_;
    if (p_ < t_.size() && ident_start(t_[p_]))
      while (p_ < t_.size() && ident_char(t_[p_])) ++p_;
    return t_.substr(b, p_ - b);
  }
  FigureName name(const std::string& expected) {
    skip();
    FigureName n{{}, at(p_)};
    n.name = word();
    if (n.name.empty()) fail(n.pos, "expected " + expected);
    return n;
  }
  void expect_word(const std::string& w, const std::string& expected) {
    skip();
    const std::size_t b = p_;
    std::string got = word();
    if (got != w) {
      std::string shown = got.empty() ? t_.substr(b, 1) : got;
      fail(at(b), "unexpected '" + shown + "'; expected " + expected, static_cast<int>(std::max<std::size_t>(1, shown.size())));
    }
  }
  // The word `with` outside parentheses at or after b, or the end.
  std::size_t find_with(std::size_t b) const {
    int depth = 0;
    for (std::size_t i = b; i < t_.size(); ++i) {
      char c = t_[i];
      if (c == '(') ++depth;
      if (c == ')') --depth;
      if (depth == 0 && ident_start(c) && (i == 0 || !ident_char(t_[i - 1]))) {
        std::size_t j = i;
        while (j < t_.size() && ident_char(t_[j])) ++j;
        if (t_.compare(i, j - i, "with") == 0 && j - i == 4) return i;
        i = j - 1;
      }
    }
    return t_.size();
  }
  Node expression(std::size_t b, std::size_t e, const std::string& what) {
    std::size_t q = nonblank(b, e);
    std::size_t r = e;
    while (r > q && blank(t_[r - 1])) --r;
    if (q >= r) fail(at(q), "expected " + what);
    return parse_expression(std::string_view(t_).substr(q, r - q), at(q));
  }
  // NAME = VALUE, ... up to e (commas inside parentheses belong to the value).
  std::vector<FigureValue> assignments(std::size_t e) {
    std::vector<FigureValue> out;
    while (true) {
      FigureValue v;
      v.name = name("'NAME = VALUE' after " + std::string(out.empty() ? "'with'" : "','"));
      skip();
      if (p_ >= e || t_[p_] != '=') fail(at(p_), "expected '=' and a value after '" + v.name.name + "'");
      ++p_;
      std::size_t b = p_, k = p_;
      int depth = 0;
      for (; k < e; ++k) {
        if (t_[k] == '(') ++depth;
        if (t_[k] == ')') --depth;
        if (t_[k] == ',' && depth == 0) break;
      }
      v.value = expression(b, k, "a value for '" + v.name.name + "' after '='");
      for (const auto& o : out)
        if (o.name.name == v.name.name)
          fail(v.name.pos, "'" + v.name.name + "' is given twice after 'with'", static_cast<int>(v.name.name.size()));
      out.push_back(std::move(v));
      p_ = k;
      if (p_ >= e) break;
      ++p_;   // the comma
    }
    return out;
  }
};

}  // namespace

FigureSpec parse_figure_spec(const ProseSource& src,
                             const std::function<void(const SourcePos&, const std::string&, int)>& fail) {
  return SpecParser(src, fail).run();
}

}  // namespace dc
