// Figures drawn by the code (docs/latex.md, "Figures"): `derivcheck latex -o OUT.tex` writes
// each drawn figure's data beside OUT.tex as OUT-figN.dat and a pgfplots picture reading it;
// the values are the file's own formulas evaluated exactly, byte-identical across runs; a bad
// figure line is a positioned error (exit 2) that writes nothing; the handout with its drawn
// figures compiles with plain pdflatex, twice, with no overfull box.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <ginac/ginac.h>

#include "derivations/reader/derivation.hpp"
#include "derivations/reader/figures.hpp"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Run {
  int rc = -1;
  std::string err;
};

Run latex(const std::string& args, const fs::path& dir) {
  const fs::path err = dir / "stderr.txt";
  std::string cmd = std::string("'") + DERIVCHECK_CLI + "' latex " + args + " > /dev/null 2> '" + err.string() + "'";
  int rc = std::system(cmd.c_str());
  return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, slurp(err)};
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::vector<double> numbers(const std::string& line) {
  std::vector<double> out;
  std::istringstream in(line);
  for (std::string w; in >> w;) out.push_back(w == "nan" ? std::nan("") : std::stod(w));
  return out;
}

std::string fixture() { return std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/latex/figures.dc"; }

fs::path fresh_dir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("dc_figures_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// %.9g of an exact GiNaC number, as the data file prints it
std::string printed(const GiNaC::ex& exact) {
  const double v = GiNaC::ex_to<GiNaC::numeric>(exact.evalf()).to_double();
  if (v == 0) return "0";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

TEST_CASE("a plot figure: data beside the .tex from the file's formulas, pgfplots reading it", "[latex][figures]") {
  REQUIRE(fs::exists(DERIVCHECK_CLI));
  const fs::path dir = fresh_dir("plot");
  const Run r = latex("'" + fixture() + "' -o '" + (dir / "fig.tex").string() + "'", dir);
  INFO(r.err);
  REQUIRE(r.rc == 0);
  const std::string tex = slurp(dir / "fig.tex");
  // the first figure is drawn; the second (no spec) stays a box; no data file for it
  CHECK(tex.find("\\usepackage{pgfplots}\n\\pgfplotsset{compat=1.18}") != std::string::npos);
  CHECK(tex.find("\\addplot+[thick, mark=none] table[x index=0, y index=1] {fig-fig1.dat};\n"
                 "\\addlegendentry{$y$}\n"
                 "\\addplot+[thick, mark=none] table[x index=0, y index=2] {fig-fig1.dat};\n"
                 "\\addlegendentry{$z$}") != std::string::npos);
  CHECK(tex.find("xlabel={$x$ [$\\mathrm{m}$]}, ylabel={$y$, $z$ [$\\mathrm{m}$]}") != std::string::npos);
  CHECK(tex.find("\\fbox{\\parbox{0.8\\linewidth}{\\centering\\vspace{3ex}\\textit{Figure:} A sketch") != std::string::npos);
  CHECK(fs::exists(dir / "fig-fig1.dat"));
  CHECK_FALSE(fs::exists(dir / "fig-fig2.dat"));

  // the rows: x = -1 + i/100, y = 1/2 + 3 x^2, z = 1/2 - x, each exact value printed with %.9g
  const auto rows = lines(slurp(dir / "fig-fig1.dat"));
  REQUIRE(rows.size() == 202);
  CHECK(rows[0] == "x y1 y2");
  for (int i = 0; i <= 200; ++i) {
    const GiNaC::numeric x = GiNaC::numeric(-1) + GiNaC::numeric(i, 100);
    const GiNaC::ex y = GiNaC::numeric(1, 2) + 3 * x * x, z = GiNaC::numeric(1, 2) - x;
    CAPTURE(i);
    CHECK(rows[static_cast<std::size_t>(i) + 1] == printed(x) + " " + printed(y) + " " + printed(z));
  }
  // and against the formulas as the reader gives them, evaluated independently of the writer
  const dc::Derivation d = dc::load_derivation(fixture());
  const dc::Formula f = dc::formula(d, "para");
  GiNaC::exmap at{{d.symbols.find("a")->sym, GiNaC::numeric(1, 2)},
                  {d.symbols.find("k")->sym, 3},
                  {d.symbols.find("x")->sym, GiNaC::numeric(1, 4)}};
  CHECK(rows[126] == "0.25 " + printed(f.expr.subs(at)) + " 0.25");
  CHECK(printed(f.expr.subs(at)) == "0.6875");
  fs::remove_all(dir);
}

TEST_CASE("latex to stdout: the figure's table stands inline, no data file", "[latex][figures]") {
  REQUIRE(fs::exists(DERIVCHECK_CLI));
  const fs::path dir = fresh_dir("stdout");
  const std::string cmd = "cd '" + dir.string() + "' && '" + DERIVCHECK_CLI + "' latex '" + fixture() + "' > out.txt 2> err.txt";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string tex = slurp(dir / "out.txt");
  CHECK(tex.find("\\addplot+[thick, mark=none] table[x index=0, y index=1, row sep=\\\\] {\nx y1 y2\\\\\n-1 3.5 1.5\\\\\n") !=
        std::string::npos);
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.path().extension() == ".dat";
  CHECK(files == 0);
  fs::remove_all(dir);
}

TEST_CASE("the reader keeps what draws each figure, with positions", "[latex][figures]") {
  const dc::Derivation d = dc::load_derivation(fixture());
  const auto specs = dc::figure_specs(d);
  REQUIRE(specs.size() == 1);   // the bare `figure "..."` is not listed
  const dc::FigureSpec& s = specs.begin()->second;
  CHECK(d.prose[specs.begin()->first].kind == dc::Prose::Kind::Figure);
  CHECK(s.kind == dc::FigureSpec::Kind::Plot);
  REQUIRE(s.curves.size() == 2);
  CHECK(s.curves[1].name == "line");
  CHECK(s.curves[1].pos.line == 15);
  CHECK(s.curves[1].pos.col == 16);
  CHECK(s.var.name == "x");
  CHECK(dc::to_text(s.lo) == "-1");
  REQUIRE(s.with.size() == 2);
  CHECK(s.with[0].name.name == "a");
  CHECK(dc::to_text(s.with[0].value) == "1/2");
}

TEST_CASE("latex with figures: two runs give the same .tex and data bytes", "[latex][figures]") {
  REQUIRE(fs::exists(DERIVCHECK_CLI));
  const fs::path a = fresh_dir("det_a"), b = fresh_dir("det_b");
  const std::string h9 = std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9";
  for (const fs::path& dir : {a, b}) {
    const Run r = latex("'" + h9 + "' '" + fixture() + "' -o '" + (dir / "h.tex").string() + "'", dir);
    INFO(r.err);
    REQUIRE(r.rc == 0);
  }
  int data_files = 0;
  for (const auto& e : fs::directory_iterator(a)) {
    if (e.path().extension() != ".dat" && e.path().extension() != ".tex") continue;
    data_files += e.path().extension() == ".dat";
    CAPTURE(e.path().filename().string());
    CHECK(slurp(e.path()) == slurp(b / e.path().filename()));
  }
  CHECK(data_files == 5);   // Example 9.3's simulation, three handout plots, the fixture's plot
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST_CASE("Example 9.3's figure is the spring simulation: the centre of mass moves uniformly", "[latex][figures]") {
  REQUIRE(fs::exists(DERIVCHECK_CLI));
  const fs::path dir = fresh_dir("spring");
  const std::string h9 = std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9";
  const Run r = latex("'" + h9 + "/04_system_of_particles.dc' -o '" + (dir / "ex.tex").string() + "'", dir);
  INFO(r.err);
  REQUIRE(r.rc == 0);
  const std::string tex = slurp(dir / "ex.tex");
  // the file's second figure (the first is a sketch)
  CHECK(tex.find("{ex-fig2.dat};\n\\addlegendentry{$x_G$}") != std::string::npos);
  const auto rows = lines(slurp(dir / "ex-fig2.dat"));
  REQUIRE(rows.size() > 100);
  CHECK(rows[0] == "x y1 y2 y3");
  // columns t, x1, x2, x_G; x_G(0) = m2 L0/(m1 + m2) = 2/3 m, v_G = 4/3 m/s (vG_example)
  double max_dev = 0, max_x1_dev = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto v = numbers(rows[i]);
    REQUIRE(v.size() == 4);
    max_dev = std::max(max_dev, std::abs(v[3] - (2.0 / 3 + 4.0 / 3 * v[0])));
    max_x1_dev = std::max(max_x1_dev, std::abs(v[1] - 4.0 / 3 * v[0]));
  }
  CHECK(numbers(rows.back())[0] == Approx(10));
  CHECK(max_dev < 1e-6);      // uniform motion of the centre of mass
  CHECK(max_x1_dev > 0.1);    // while the masses themselves do not move uniformly
  fs::remove_all(dir);
}

TEST_CASE("bad figure lines: positioned errors, exit 2, no .tex and no data written", "[latex][figures]") {
  REQUIRE(fs::exists(DERIVCHECK_CLI));
  const fs::path dir = fresh_dir("bad");
  const std::string head =
      "title \"bad figures\"\nsymbol x, y, z : real [m]\nsymbol a : positive [m]\nsymbol k : positive [1/m]\n"
      "para: y = a + k*x^2\n    by given\nsum: y + z = a\n    by given\nroot: z = sqrt(x*a)\n    by given\n";
  struct Case {
    std::string figure, where, message;
  };
  const std::vector<Case> cases = {
      {"figure \"c\" plot nosuch over x = 0 .. 1 with a = 1, k = 1", ":11:17: error:", "no step labelled 'nosuch'"},
      {"figure \"c\" plot sum over x = 0 .. 1 with a = 1, k = 1", ":11:17: error:", "not of the form 'y = expression'"},
      {"figure \"c\" plot para over x = 1 .. 1 with a = 1, k = 1", ":11:31: error:", "empty or reversed range"},
      {"figure \"c\" plot para over x = 2 .. -1 with a = 1, k = 1", ":11:31: error:", "empty or reversed range"},
      {"figure \"c\" plot para over x = 0 .. 1 with a = 1", ":11:17: error:", "symbol 'k' of 'para' has no value"},
      {"figure \"c\" simulate nosuch", ":11:21: error:", "unknown scene 'nosuch'"},
      {"figure \"c\" plot para over x = 0 .. 1 with a = 0, k = 1", ":11:47: error:", "outside its declared domain"},
      {"figure \"c\" plot root over x = -2 .. -1 with a = 1", ":11:17: error:", "'root' has no real value anywhere"},
      {"figure \"c\" plot para over q = 0 .. 1 with a = 1, k = 1", ":11:27: error:", "'q' is not a declared symbol"},
      {"figure \"c\" plot para x = 0 .. 1", ":11:22: error:", "expected 'over X = LO .. HI'"},
      {"figure \"c\" draw para", ":11:12: error:", "expected 'simulate SCENE' or 'plot LABEL"},
      {"figure \"c\" simulate spring with mass = 2", ":11:33: error:", "scene 'spring' has no parameter 'mass'"},
  };
  const fs::path src = dir / "src", out_dir = dir / "out";
  fs::create_directories(src);
  fs::create_directories(out_dir);
  int n = 0;
  for (const auto& c : cases) {
    const fs::path in = src / ("bad" + std::to_string(++n) + ".dc");
    std::ofstream(in) << head << c.figure << "\n";
    const fs::path out = out_dir / ("out" + std::to_string(n) + ".tex");
    const Run r = latex("'" + in.string() + "' -o '" + out.string() + "'", dir);
    CAPTURE(c.figure, r.err);
    CHECK(r.rc == 2);
    CHECK(r.err.find(in.string() + c.where) != std::string::npos);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
    CHECK_FALSE(fs::exists(out_dir / ("out" + std::to_string(n) + "-fig1.dat")));
  }
  // a file with a good drawn figure and a bad one: neither data file nor .tex is written
  const fs::path mixed = src / "mixed.dc";
  std::ofstream(mixed) << head << "figure \"good\" plot para over x = 0 .. 1 with a = 1, k = 1\n"
                       << "figure \"bad\" plot para over x = 0 .. 1 with a = 1\n";
  Run r = latex("'" + mixed.string() + "' -o '" + (out_dir / "mixed.tex").string() + "'", dir);
  CHECK(r.rc == 2);
  CHECK_FALSE(fs::exists(out_dir / "mixed.tex"));
  CHECK_FALSE(fs::exists(out_dir / "mixed-fig1.dat"));
  // a good figure, but the .tex would sit in the source folder: its data would too, refused
  const fs::path good = src / "good.dc";
  std::ofstream(good) << head << "figure \"good\" plot para over x = 0 .. 1 with a = 1, k = 1\n";
  r = latex("'" + good.string() + "' -o '" + (src / "good.tex").string() + "'", dir);
  CAPTURE(r.err);
  CHECK(r.rc == 2);
  CHECK(r.err.find("outside the source folder") != std::string::npos);
  CHECK_FALSE(fs::exists(src / "good.tex"));
  CHECK_FALSE(fs::exists(src / "good-fig1.dat"));
  r = latex("'" + good.string() + "' -o '" + (out_dir / "good.tex").string() + "'", dir);
  CHECK(r.rc == 0);
  CHECK(fs::exists(out_dir / "good-fig1.dat"));
  fs::remove_all(dir);
}

TEST_CASE("the handout with its drawn figures compiles with plain pdflatex, no overfull box", "[latex][figures][pdflatex]") {
  if (std::system("command -v pdflatex > /dev/null 2>&1") != 0 ||
      std::system("kpsewhich pgfplots.sty > /dev/null 2>&1") != 0) {
    WARN("pdflatex or pgfplots not installed: compile test skipped (tools/install-deps.sh installs them)");
    return;
  }
  const fs::path dir = fresh_dir("pdf");
  const std::string h9 = std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9";
  const Run r = latex("'" + h9 + "' -o '" + (dir / "handout9.tex").string() + "'", dir);
  INFO(r.err);
  REQUIRE(r.rc == 0);
  const std::string tex = slurp(dir / "handout9.tex");
  int pictures = 0;
  for (std::size_t p = tex.find("\\begin{tikzpicture}"); p != std::string::npos; p = tex.find("\\begin{tikzpicture}", p + 1))
    ++pictures;
  CHECK(pictures == 4);
  // plain pdflatex (no -shell-escape), twice, in the .tex's folder
  const std::string pass = "pdflatex -no-shell-escape -halt-on-error -interaction=nonstopmode handout9.tex > build.log 2>&1";
  const int rc = std::system(("cd '" + dir.string() + "' && " + pass + " && " + pass).c_str());
  const std::string log = slurp(dir / "handout9.log");
  INFO(slurp(dir / "build.log").substr(0, 3000));
  REQUIRE(rc == 0);
  REQUIRE(fs::exists(dir / "handout9.pdf"));
  std::vector<std::string> overfull;
  for (const auto& l : lines(log))
    if (l.rfind("Overfull \\", 0) == 0) overfull.push_back(l);
  CAPTURE(overfull);
  CHECK(overfull.empty());
  CHECK(log.find("pgfplots") != std::string::npos);
  fs::remove_all(dir);
}
