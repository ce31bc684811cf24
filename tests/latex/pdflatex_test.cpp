// The emitted handout compiles with pdflatex (standalone, annotated, and a fragment \input into a
// plain article with amsmath only) with no overfull box and no moved margin note in any of the
// logs, and the standalone PDF carries the author's prose (pdftotext). Skipped with a warning only
// when pdflatex is not installed.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "derivations/reader/derivation.hpp"
#include "derivations/syntax/io.hpp"
#include "derivations/report/latex.hpp"
#include "derivations/rules/check.hpp"

namespace fs = std::filesystem;

namespace {

bool have_pdflatex() { return std::system("command -v pdflatex > /dev/null 2>&1") == 0; }

std::vector<dc::Derivation> handout() {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(fs::path(DERIVCHECK_SOURCE_DIR) / "derivations/handout9"))
    if (e.path().extension() == ".dc") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  std::vector<dc::Derivation> ds;
  for (const auto& f : files) ds.push_back(dc::load_derivation(f));
  return ds;
}

struct Compiled {
  std::string failure;   // "" when the PDF was produced
  std::string log;       // pdflatex's .log of the last pass
  std::string text;      // pdftotext of the PDF ("" without pdftotext)
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Compile `tex` as NAME.tex in a fresh directory (two passes, as a lecturer would).
Compiled compile(const std::string& name, const std::string& tex, const std::string& extra_name = {},
                 const std::string& extra = {}) {
  fs::path dir = fs::temp_directory_path() / ("dc_pdflatex_" + std::to_string(::getpid()) + "_" + name);
  fs::create_directories(dir);
  dc::write_file_atomic((dir / (name + ".tex")).string(), tex);
  if (!extra_name.empty()) dc::write_file_atomic((dir / extra_name).string(), extra);
  std::string pass = "pdflatex -halt-on-error -interaction=nonstopmode " + name + ".tex > build.log 2>&1";
  std::string cmd = "cd '" + dir.string() + "' && " + pass + " && " + pass;
  int rc = std::system(cmd.c_str());
  Compiled c;
  c.log = slurp(dir / (name + ".log"));
  if (rc != 0 || !fs::exists(dir / (name + ".pdf")) || fs::file_size(dir / (name + ".pdf")) < 1000) {
    std::string b = slurp(dir / "build.log");
    c.failure = "pdflatex failed (rc " + std::to_string(rc) + "):\n" + b.substr(b.size() > 3000 ? b.size() - 3000 : 0);
  } else if (std::system("command -v pdftotext > /dev/null 2>&1") == 0) {
    std::string t = "cd '" + dir.string() + "' && pdftotext " + name + ".pdf out.txt";
    if (std::system(t.c_str()) == 0) c.text = slurp(dir / "out.txt");
  }
  fs::remove_all(dir);
  return c;
}

// The log lines of every overfull box and every "Marginpar ... moved", with the line after.
std::vector<std::string> layout_warnings(const std::string& log) {
  std::vector<std::string> out;
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("Overfull \\", 0) == 0 || line.find("Marginpar") != std::string::npos) {
      std::string next;
      std::getline(in, next);
      out.push_back(line + " | " + next);
    }
  }
  return out;
}

// Words of three or more letters, as the issue counts the handout's prose.
int words(const std::string& text) {
  int n = 0, run = 0;
  for (char ch : text) {
    if (std::isalpha(static_cast<unsigned char>(ch))) {
      ++run;
    } else {
      if (run >= 3) ++n;
      run = 0;
    }
  }
  return n + (run >= 3);
}

}  // namespace

TEST_CASE("emitted handout compiles with pdflatex", "[latex][pdflatex]") {
  if (!have_pdflatex()) {
    WARN("pdflatex not installed: compile test skipped (tools/install-deps.sh installs it)");
    return;
  }
  auto ds = handout();
  std::vector<const dc::Derivation*> ptrs;
  for (const auto& d : ds) ptrs.push_back(&d);
  dc::LatexOptions opt;
  opt.title = "Handout 9 – Linear Momentum, Impact and Rockets";

  SECTION("standalone: compiles, no overfull box, reads as a handout") {
    Compiled c = compile("handout9", dc::write_latex(ptrs, opt));
    INFO(c.failure);
    REQUIRE(c.failure.empty());
    auto warnings = layout_warnings(c.log);
    CAPTURE(warnings);
    CHECK(warnings.empty());
    if (c.text.empty()) {
      WARN("pdftotext not installed: the prose word count is not checked");
    } else {
      // the author's text is in the handout, not only equations
      CHECK(words(c.text) >= 1200);
      CHECK(c.text.find("Purely elastic impact") != std::string::npos);
    }
  }
  SECTION("annotated, with verdicts: no overfull box, no moved margin note") {
    std::vector<dc::CheckSummary> sums;
    std::vector<const dc::CheckSummary*> checks;
    for (const auto& d : ds) sums.push_back(dc::check_derivation(d));
    for (const auto& s : sums) checks.push_back(&s);
    opt.annotate = true;
    opt.checks = &checks;
    std::string tex = dc::write_latex(ptrs, opt);
    CHECK(tex.find("proved") != std::string::npos);
    Compiled c = compile("annotated", tex);
    INFO(c.failure);
    REQUIRE(c.failure.empty());
    auto warnings = layout_warnings(c.log);
    CAPTURE(warnings);
    CHECK(warnings.empty());
  }
  SECTION("with --units: the quantities and their units (siunitx), no overfull box") {
    if (std::system("kpsewhich siunitx.sty > /dev/null 2>&1") != 0) {
      WARN("siunitx not installed: --units compile test skipped (tools/install-deps.sh installs texlive-science)");
      return;
    }
    opt.units = true;
    std::string tex = dc::write_latex(ptrs, opt);
    CHECK(tex.find("\\usepackage{siunitx}") != std::string::npos);
    CHECK(tex.find("$m_1$, $m_2$ in \\si{kg}; $v_1$, $v_2$, $v'_1$, $v'_2$ in \\si{m/s}") != std::string::npos);
    CHECK(tex.find("$\\Delta T$, $T'$ in \\si{J}") != std::string::npos);
    Compiled c = compile("units", tex);
    INFO(c.failure);
    REQUIRE(c.failure.empty());
    auto warnings = layout_warnings(c.log);
    CAPTURE(warnings);
    CHECK(warnings.empty());
    if (!c.text.empty()) CHECK(c.text.find("Quantities.") != std::string::npos);
  }
  SECTION("fragment \\input into a plain article with amsmath only: no overfull box") {
    opt.fragment = true;
    std::string frag = dc::write_latex(ptrs, opt);
    CHECK(frag.find("\\documentclass") == std::string::npos);
    CHECK(frag.find("\\begin{document}") == std::string::npos);
    // exactly the preamble docs/cli.md documents for --fragment
    std::string main = "\\documentclass{article}\n\\usepackage{amsmath,amssymb}\n\\begin{document}\n"
                       "\\input{handout9-fragment}\n\\end{document}\n";
    Compiled c = compile("main", main, "handout9-fragment.tex", frag);
    INFO(c.failure);
    REQUIRE(c.failure.empty());
    auto warnings = layout_warnings(c.log);
    CAPTURE(warnings);
    CHECK(warnings.empty());
  }
}

// The typesetting fixture (tests/data/latex/typesetting.dc: § and other Unicode in prose, paired
// quotes, emphasis with math, a caption with markup, inline quotients, Greek subscripts, a
// definition's tex, a limit step's condition, the file's handout title, --units with defined
// quantities) compiles standalone and with --units, with no overfull box.
TEST_CASE("typesetting fixture compiles with pdflatex, no overfull box", "[latex][pdflatex]") {
  if (!have_pdflatex()) {
    WARN("pdflatex not installed: compile test skipped (tools/install-deps.sh installs it)");
    return;
  }
  const dc::Derivation d =
      dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/latex/typesetting.dc");
  dc::LatexOptions opt;
  opt.units = std::system("kpsewhich siunitx.sty > /dev/null 2>&1") == 0;
  const std::string tex = dc::write_latex(d, opt);
  Compiled c = compile("typesetting", tex);
  INFO(c.failure);
  REQUIRE(c.failure.empty());
  auto warnings = layout_warnings(c.log);
  CAPTURE(warnings);
  CHECK(warnings.empty());
  if (!c.text.empty()) {
    CHECK(c.text.find("U+") == std::string::npos);
    CHECK(c.text.find("Handout 10") != std::string::npos);
    CHECK(c.text.find("\xC2\xA7" "10.3") != std::string::npos);   // the section sign itself
  }
}
