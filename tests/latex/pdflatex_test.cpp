// The emitted handout compiles with pdflatex (standalone, annotated, and a fragment \input
// into a minimal document). Skipped with a warning only when pdflatex is not installed.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "derivations/core/derivation.hpp"
#include "derivations/core/io.hpp"
#include "derivations/core/latex.hpp"
#include "derivations/core/rules.hpp"

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

// Compile `tex` as NAME.tex in a fresh directory; returns the log on failure ("" on success).
std::string compile(const std::string& name, const std::string& tex, const std::string& extra_name = {},
                    const std::string& extra = {}) {
  fs::path dir = fs::temp_directory_path() / ("dc_pdflatex_" + std::to_string(::getpid()) + "_" + name);
  fs::create_directories(dir);
  dc::write_file_atomic((dir / (name + ".tex")).string(), tex);
  if (!extra_name.empty()) dc::write_file_atomic((dir / extra_name).string(), extra);
  std::string cmd = "cd '" + dir.string() + "' && pdflatex -halt-on-error -interaction=nonstopmode " + name +
                    ".tex > build.log 2>&1";
  int rc = std::system(cmd.c_str());
  std::string out;
  if (rc != 0 || !fs::exists(dir / (name + ".pdf")) || fs::file_size(dir / (name + ".pdf")) < 1000) {
    std::ifstream in(dir / "build.log");
    std::ostringstream ss;
    ss << in.rdbuf();
    out = "pdflatex failed (rc " + std::to_string(rc) + "):\n" + ss.str().substr(ss.str().size() > 3000 ? ss.str().size() - 3000 : 0);
  }
  fs::remove_all(dir);
  return out;
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

  SECTION("standalone") {
    std::string log = compile("handout9", dc::write_latex(ptrs, opt));
    INFO(log);
    CHECK(log.empty());
  }
  SECTION("annotated, with verdicts") {
    std::vector<dc::CheckSummary> sums;
    std::vector<const dc::CheckSummary*> checks;
    for (const auto& d : ds) sums.push_back(dc::check_derivation(d));
    for (const auto& s : sums) checks.push_back(&s);
    opt.annotate = true;
    opt.checks = &checks;
    std::string tex = dc::write_latex(ptrs, opt);
    CHECK(tex.find("\\marginpar") != std::string::npos);
    CHECK(tex.find("proved") != std::string::npos);
    std::string log = compile("annotated", tex);
    INFO(log);
    CHECK(log.empty());
  }
  SECTION("fragment \\input into a document") {
    opt.fragment = true;
    std::string frag = dc::write_latex(ptrs, opt);
    CHECK(frag.find("\\documentclass") == std::string::npos);
    CHECK(frag.find("\\begin{document}") == std::string::npos);
    std::string main = "\\documentclass{article}\n\\usepackage{amsmath,amssymb}\n\\begin{document}\n"
                       "\\input{handout9-fragment}\n\\end{document}\n";
    std::string log = compile("main", main, "handout9-fragment.tex", frag);
    INFO(log);
    CHECK(log.empty());
  }
}
