// Golden files: tests/golden/STEM.tex is the approved standalone LaTeX of
// derivations/handout9/STEM.dc, as `derivcheck latex STEM.dc -o STEM.tex` writes it, and
// STEM-figN.dat the data of its drawn figures; all compared byte for byte. Regenerate after an
// intended change with
//   tools/update-golden.sh build/derivcheck      (then review `git diff tests/golden`)
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "derivations/reader/derivation.hpp"
#include "derivations/report/latex.hpp"
#include "numeric/charts/figure_data.hpp"

namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
// The first line where two texts differ, for the failure message.
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream ia(a), ib(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    bool ga = static_cast<bool>(std::getline(ia, la)), gb = static_cast<bool>(std::getline(ib, lb));
    if (!ga && !gb) return "identical";
    if (la != lb || ga != gb)
      return "line " + std::to_string(line) + ":\n  golden: " + (gb ? lb : "<end>") + "\n  now:    " + (ga ? la : "<end>");
  }
}
}  // namespace

TEST_CASE("latex golden files match byte for byte", "[latex][golden]") {
  fs::path root(DERIVCHECK_SOURCE_DIR);
  std::vector<fs::path> sources;
  for (const auto& e : fs::directory_iterator(root / "derivations/handout9"))
    if (e.path().extension() == ".dc") sources.push_back(e.path());
  std::sort(sources.begin(), sources.end());
  REQUIRE(!sources.empty());
  std::size_t goldens = 0;
  for (const auto& e : fs::directory_iterator(root / "tests/golden")) goldens += e.path().extension() == ".tex";
  CHECK(goldens == sources.size());  // no stale golden files either
  for (const auto& src : sources) {
    fs::path golden = root / "tests/golden" / (src.stem().string() + ".tex");
    CAPTURE(src.string(), golden.string());
    REQUIRE(fs::exists(golden));
    const dc::Derivation d = dc::load_derivation(src.string());
    const dc::chart::DrawnFigures figures = dc::chart::draw_figures({&d}, src.stem().string());
    dc::LatexOptions opt;
    opt.drawn_figures = &figures.pictures;
    std::string now = dc::write_latex(d, opt);
    std::string approved = slurp(golden);
    INFO(first_difference(now, approved) << "\n(regenerate with tools/update-golden.sh if intended)");
    CHECK(now == approved);
    for (const auto& [name, text] : figures.files) {
      CAPTURE(name);
      REQUIRE(fs::exists(root / "tests/golden" / name));
      CHECK(text == slurp(root / "tests/golden" / name));
    }
  }
}
