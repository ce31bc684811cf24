// The checked web page (html.hpp). The page's text is the LaTeX handout's: headings from
// handout_heading, prose pieces with latex_prose_math, each step's rows from latex_step_rows
// (the same line breaks and "(as x -> p)" conditions as the PDF), and the evidence under a mark
// is format_step_text, what `derivcheck check` prints for the step. Only the HTML around them
// is written here.
#include "derivations/report/html.hpp"

#include <cctype>
#include <map>
#include <stdexcept>

#include "derivations/report/latex.hpp"
#include "derivations/report/report.hpp"

namespace dc {
namespace {

std::string basename_of(const std::string& path) {
  auto s = path.find_last_of('/');
  return s == std::string::npos ? path : path.substr(s + 1);
}

// An id from a file name or label: letters, digits, '-' and '_' kept, anything else '-'.
std::string id_part(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += std::isalnum(c) || c == '-' || c == '_' ? static_cast<char>(c) : '-';
  return out.empty() ? "x" : out;
}

std::string prose_html(const std::vector<ProsePiece>& pieces, const SymbolTable& table, const LatexStyle& style) {
  std::string out;
  for (const auto& p : pieces) {
    switch (p.kind) {
      case ProsePiece::Kind::Text: out += html_escape(p.text); break;
      case ProsePiece::Kind::Emph:
        out += "<em>" + (p.inner.empty() ? html_escape(p.text) : prose_html(p.inner, table, style)) + "</em>";
        break;
      case ProsePiece::Kind::Math:
      case ProsePiece::Kind::Expr: out += "\\(" + html_escape(latex_prose_math(p, table, style)) + "\\)"; break;
    }
  }
  return out;
}

const char* kStyle = R"css(
:root { --ink: #1d1d1f; --muted: #5f6368; --rule: #d9d9de; --paper: #ffffff; --tint: #f5f6f8;
        --proved: #1a7f37; --numeric: #0b62c4; --refuted: #c62828; --undecided: #9a6700; --premise: #6e6e73; }
html { background: var(--paper); }
body { color: var(--ink); font: 17px/1.6 "DejaVu Serif", Georgia, serif; max-width: 50rem; margin: 0 auto;
       padding: 1.5rem 1.25rem 4rem; }
header h1 { font-size: 1.8rem; line-height: 1.25; margin: .4rem 0 .2rem; }
header p { margin: .2rem 0; }
.subtitle { color: var(--muted); }
.summary, .legend { font: .85rem/1.5 "DejaVu Sans", system-ui, sans-serif; color: var(--muted); }
.legend .mark { margin: 0 .3em 0 .6em; }
h2 { font-size: 1.35rem; margin: 2.4rem 0 .6rem; border-bottom: 1px solid var(--rule); padding-bottom: .2rem; }
h2 .number { color: var(--muted); margin-right: .6em; }
h3 { font-size: 1.1rem; margin: 1.6rem 0 .4rem; }
p { margin: .55rem 0; }
a { color: var(--numeric); }
nav.toc { background: var(--tint); border: 1px solid var(--rule); border-radius: 6px; padding: .6rem 1.2rem;
          margin: 1.2rem 0 1.6rem; font: .92rem/1.5 "DejaVu Sans", system-ui, sans-serif; }
nav.toc h2 { font-size: 1rem; border: 0; margin: .2rem 0; padding: 0; }
nav.toc ol { margin: .1rem 0; padding-left: 0; list-style: none; }
nav.toc > ol { columns: 2; column-gap: 2rem; }
nav.toc > ol > li { break-inside: avoid; margin-bottom: .3rem; }
nav.toc ol ol { font-size: .85rem; padding-left: 1rem; color: var(--muted); }
nav.toc a { color: var(--ink); text-decoration: none; }
nav.toc a:hover { text-decoration: underline; }
.step { display: grid; grid-template-columns: minmax(0, 1fr) auto; align-items: center; column-gap: .8rem;
        margin: .15rem 0; }
.step > .eq { overflow-x: auto; overflow-y: hidden; }
.step > .eq .katex-display { margin: .45rem 0; }
.step > details { justify-self: end; }
.step > details[open] { grid-column: 1 / -1; justify-self: stretch; margin-bottom: .6rem; }
.step > details[open] > summary { text-align: right; }
.step > .erratum { grid-column: 1 / -1; font-size: .9rem; color: var(--muted); margin: 0 0 .5rem; }
summary { cursor: pointer; list-style: none; }
summary::-webkit-details-marker { display: none; }
.mark { display: inline-block; min-width: 1.7em; padding: 0 .4em; border-radius: .85em; text-align: center;
        font: 600 .8rem/1.7 "DejaVu Sans", system-ui, sans-serif; color: #fff; }
.m-proved { background: var(--proved); }
.m-numeric { background: var(--numeric); }
.m-refuted, .m-error { background: var(--refuted); }
.m-undecided { background: var(--undecided); }
.m-premise { background: transparent; color: var(--premise); border: 1px solid var(--premise); font-weight: 400; }
.why { font: .84rem/1.45 "DejaVu Sans", system-ui, sans-serif; background: var(--tint);
       border-left: 3px solid var(--rule); padding: .35rem .8rem; margin-top: .3rem; }
.why pre { font: .78rem/1.45 "DejaVu Sans Mono", monospace; white-space: pre-wrap; overflow-wrap: anywhere;
           margin: .3rem 0; }
.why ul { margin: .2rem 0; padding-left: 1.2rem; }
details.helpers { margin: .3rem 0 .6rem; }
details.helpers > summary { font: .82rem/1.5 "DejaVu Sans", system-ui, sans-serif; color: var(--muted); }
details.helpers > summary::before { content: "\25B8  "; }
details.helpers[open] > summary::before { content: "\25BE  "; }
details.helpers[open] { border-left: 2px dotted var(--rule); padding-left: .8rem; }
figure.placeholder { border: 1px dashed #9a9aa0; border-radius: 4px; margin: 1.2rem 2rem; padding: 1.6rem 1.2rem;
                     text-align: center; }
figure.placeholder figcaption { font-style: italic; }
figure.plot { margin: 1.2rem 0; text-align: center; }
figure.plot svg { max-width: 100%; height: auto; font-family: sans-serif; }
figure.plot .axes { font-size: 0.85rem; color: #444; margin: 0.2rem 0; }
figure.plot figcaption { font-style: italic; }
.remark-label { font-weight: bold; }
footer { margin-top: 3rem; border-top: 1px solid var(--rule); padding-top: .5rem;
         font: .8rem/1.5 "DejaVu Sans", system-ui, sans-serif; color: var(--muted); }
@media print {
  @page { margin: 18mm 16mm; }
  body { max-width: none; padding: 0; font-size: 10.5pt; }
  a { color: inherit; text-decoration: none; }
  nav.toc { break-after: page; background: none; }
  h2, h3 { break-after: avoid; }
  .step, figure { break-inside: avoid; }
  .step > details[open] { grid-column: 2; justify-self: end; }
  .why, details.helpers, .legend, footer { display: none; }
  .mark { color: var(--ink); background: none; border: 1px solid var(--ink); }
  .step > .eq { overflow: visible; }
}
)css";

const char* kRender = R"js(
renderMathInElement(document.body, {
  delimiters: [{left: "\\[", right: "\\]", display: true}, {left: "\\(", right: "\\)", display: false}],
  ignoredTags: ["script", "noscript", "style", "textarea", "pre", "code", "option"]
});
)js";

class PageWriter {
 public:
  explicit PageWriter(const std::map<const Prose*, std::string>* figures) : figures_(figures) {}
  std::string section(const Derivation& d, const CheckSummary& checks, const std::string& id) {
    const LatexStyle style = latex_style_of(d);
    const HandoutHeading h = handout_heading(d);
    std::string out = "<section id=\"" + id + "\">\n<h2>";
    if (!h.number.empty()) out += "<span class=\"number\">" + html_escape(h.number) + "</span>";
    out += html_escape(h.title) + "</h2>\n";
    toc_ += "<li><a href=\"#" + id + "\">" + (h.number.empty() ? "" : html_escape(h.number) + " ") +
            html_escape(h.title) + "</a>";
    std::string sub_toc;
    int headings = 0;
    std::vector<std::size_t> helpers;   // steps left out of the printed handout, waiting to be folded
    auto flush_helpers = [&] {
      if (helpers.empty()) return;
      out += "<details class=\"helpers\"><summary>" + std::to_string(helpers.size()) +
             (helpers.size() == 1 ? " checked step" : " checked steps") +
             " not in the printed handout</summary>\n";
      for (std::size_t i : helpers) out += step(d, d.steps[i], checks.results[i], id);
      out += "</details>\n";
      helpers.clear();
    };
    std::size_t next_prose = 0;
    auto prose_before = [&](std::size_t step_index) {
      while (next_prose < d.prose.size() && d.prose[next_prose].before_step <= step_index) {
        flush_helpers();
        const Prose& p = d.prose[next_prose++];
        const std::string text = prose_html(p.pieces, d.symbols, style);
        switch (p.kind) {
          case Prose::Kind::Heading: {
            const std::string hid = id + "-h" + std::to_string(++headings);
            out += "<h3 id=\"" + hid + "\">" + text + "</h3>\n";
            sub_toc += "<li><a href=\"#" + hid + "\">" + text + "</a></li>";
            break;
          }
          case Prose::Kind::Paragraph: out += "<p>" + text + "</p>\n"; break;
          case Prose::Kind::Remark: out += "<p><span class=\"remark-label\">Remark.</span> " + text + "</p>\n"; break;
          case Prose::Kind::Figure:
            // a figure the code draws is its SVG picture; a sketch stays a captioned box, as in the LaTeX
            if (figures_ && figures_->count(&p))
              out += "<figure class=\"plot\">" + figures_->at(&p) + "<figcaption>Figure: " + text +
                     "</figcaption></figure>\n";
            else
              out += "<figure class=\"placeholder\"><figcaption>Figure: " + text + "</figcaption></figure>\n";
            break;
        }
      }
    };
    for (std::size_t i = 0; i < d.steps.size(); ++i) {
      prose_before(i);
      if (step_in_handout(d.steps[i])) {
        flush_helpers();
        out += step(d, d.steps[i], checks.results[i], id);
      } else {
        helpers.push_back(i);
      }
    }
    prose_before(d.steps.size());
    flush_helpers();
    if (!sub_toc.empty()) toc_ += "<ol>" + sub_toc + "</ol>";
    toc_ += "</li>\n";
    return out + "</section>\n";
  }

  const std::string& toc() const { return toc_; }

 private:
  const std::map<const Prose*, std::string>* figures_ = nullptr;
  std::string toc_;

  static std::string step(const Derivation& d, const Step& s, const StepResult& r, const std::string& section_id) {
    const VerdictMark m = verdict_mark(r);
    const std::size_t own_errors = r.errors.size() - (r.erratum_reported ? 1 : 0);
    const std::string verdict = r.premise && r.verdict.holds() ? "premise" : to_string(r.verdict.kind);
    std::string out = "<div class=\"step\" id=\"" + section_id + "--" + id_part(s.label) + "\" data-step=\"" +
                      html_escape(basename_of(d.source.name) + ":" + s.label) + "\" data-verdict=\"" + verdict +
                      "\" data-errors=\"" + std::to_string(own_errors) + "\">\n";
    // the equation: the handout's rows in an aligned block, its tag as in the PDF
    const std::vector<std::string> rows = latex_step_rows(d, s, kLatexLineLimit);
    std::string tex = "\\begin{aligned}";
    for (std::size_t i = 0; i < rows.size(); ++i) tex += (i ? " \\\\ " : "") + rows[i];
    tex += "\\end{aligned}";
    if (!s.tag.empty()) tex += " \\tag{" + latex_escape_text(s.tag) + "}";
    out += "<div class=\"eq\">\\[" + html_escape(tex) + "\\]</div>\n";
    // the mark, and what `check` prints for the step under it
    const std::string words = r.premise && r.verdict.holds() ? std::string("premise")
                              : own_errors > 0                ? std::string("step with errors")
                                                              : verdict_phrase(r.verdict);
    out += "<details class=\"evidence\"><summary title=\"" + html_escape(words) +
           " \xE2\x80\x94 click for the evidence\"><span class=\"mark m-" + m.kind + "\">" + m.symbol +
           "</span></summary>\n<div class=\"why\">";
    const std::string rule = s.rule.text.empty() ? "by " + s.rule.written_name : s.rule.text;
    out += "<p><code>" + html_escape(s.label) + "</code>: " + html_escape(rule) + "</p>";
    out += "<pre>" + html_escape(format_step_text(s, r, ReportOptions{})) + "</pre>";
    std::string guaranteed;
    for (const auto& c : r.verdict.side_conditions)
      if (c.status == SideCondition::Status::Guaranteed)
        guaranteed += "<li>" + html_escape(c.what) + " (" + html_escape(c.reason) + ")" +
                      (c.evidence.empty() ? "" : ": " + html_escape(c.evidence)) + "</li>";
    if (!guaranteed.empty()) out += "<p>Side conditions guaranteed by the declarations:</p><ul>" + guaranteed + "</ul>";
    out += "</div></details>\n";
    if (s.erratum)
      out += "<p class=\"erratum\">Erratum: the source prints \\(" + html_escape(latex_erratum_printed(d, s)) +
             "\\); " + html_escape(s.erratum->why) + ".</p>\n";
    return out + "</div>\n";
  }
};

}  // namespace

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

VerdictMark verdict_mark(const StepResult& r) {
  const std::size_t own_errors = r.errors.size() - (r.erratum_reported ? 1 : 0);
  if (own_errors > 0) return {"\xE2\x9C\x97", "error"};                            // ✗
  switch (r.verdict.kind) {
    case VerdictKind::Refuted: return {"\xE2\x9C\x97", "refuted"};                 // ✗
    case VerdictKind::Undecided: return {"?", "undecided"};
    case VerdictKind::Proved: return r.premise ? VerdictMark{"given", "premise"} : VerdictMark{"\xE2\x9C\x93", "proved"};
    case VerdictKind::HoldsNumerically:
      return r.premise ? VerdictMark{"given", "premise"} : VerdictMark{"\xE2\x89\x88", "numeric"};   // ≈
  }
  return {"?", "undecided"};
}

std::string write_html(const std::vector<const Derivation*>& ds, const std::vector<const CheckSummary*>& checks,
                       const HtmlOptions& opt) {
  if (checks.size() != ds.size()) throw std::invalid_argument("write_html: one check summary per derivation is needed");
  PageWriter w(opt.figures);
  std::string body;
  std::map<std::string, int> ids;   // a file name twice (two folders) gets -2, -3 ...
  for (std::size_t i = 0; i < ds.size(); ++i) {
    const std::string stem = id_part(basename_of(ds[i]->source.name).substr(0, basename_of(ds[i]->source.name).rfind(".dc")));
    const int n = ++ids[stem];
    body += w.section(*ds[i], *checks[i], n == 1 ? stem : stem + "-" + std::to_string(n));
  }
  const std::string title = handout_title(ds, opt.title);
  std::string out(kHtmlGeneratorLine);
  out += " Do not edit: regenerate from the .dc files. -->\n";
  out += "<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += "<meta name=\"generator\" content=\"derivcheck html\">\n";
  out += "<title>" + html_escape(title) + "</title>\n";
  out += "<link rel=\"stylesheet\" href=\"katex/katex.min.css\">\n<style>" + std::string(kStyle) + "</style>\n";
  out += "</head>\n<body>\n<header>\n<h1>" + html_escape(title) + "</h1>\n";
  if (!opt.subtitle.empty()) out += "<p class=\"subtitle\">" + html_escape(opt.subtitle) + "</p>\n";
  if (!opt.summary.empty()) out += "<p class=\"summary\">Checked by derivcheck: " + html_escape(opt.summary) + ".</p>\n";
  out += "<p class=\"legend\">Beside every equation its verdict: "
         "<span class=\"mark m-proved\">\xE2\x9C\x93</span>proved, "
         "<span class=\"mark m-numeric\">\xE2\x89\x88</span>holds numerically, "
         "<span class=\"mark m-refuted\">\xE2\x9C\x97</span>refuted, "
         "<span class=\"mark m-undecided\">?</span>undecided, "
         "<span class=\"mark m-premise\">given</span>a premise. Click a mark for the evidence.</p>\n";
  out += "</header>\n<nav class=\"toc\">\n<h2>Contents</h2>\n<ol>\n" + w.toc() + "</ol>\n</nav>\n<main>\n";
  out += body;
  out += "</main>\n<footer>Written by <code>derivcheck html</code> from the derivation files; math typeset by "
         "KaTeX.</footer>\n";
  out += "<script src=\"katex/katex.min.js\"></script>\n<script src=\"katex/contrib/auto-render.js\"></script>\n";
  out += "<script>" + std::string(kRender) + "</script>\n</body>\n</html>\n";
  return out;
}

}  // namespace dc
