// `derivcheck html`: the site it writes (deterministic, never half written, no foreign folder
// clobbered, positioned errors for bad input), and what a real browser makes of it: headless
// Chromium renders the math of every step and shows the verdict marks of `check --json`. The
// page checker is itself tested on pages broken on purpose.
#include <catch2/catch.hpp>

#include <filesystem>
#include <map>

#include "html/browser.hpp"

namespace fs = std::filesystem;
using cli_test::run;
using cli_test::src;
using html_test::slurp;

namespace {

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / ("dc_html_" + std::to_string(::getpid()) + "_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// Every file of a folder (relative path -> bytes).
std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return out;
}

const std::string kMarks = "tests/data/html/marks.dc";

void require_chromium() {
  if (!html_test::have_chromium())
    FAIL("chromium is not installed: tools/install-deps.sh installs Debian's chromium, which this test needs");
}

}  // namespace

TEST_CASE("the handout renders in headless Chromium with check --json's marks", "[html][browser]") {
  require_chromium();
  TempDir t("handout");
  const fs::path site = t.path / "site";
  const cli_test::Run check = run({"check", "--json", src("derivations/handout9/")});
  REQUIRE(check.exit_code == 0);
  const auto expected = html_test::checked_steps(check.out);
  const cli_test::Run html = run({"html", src("derivations/handout9/"), "-o", site.string()});
  INFO(html.err);
  REQUIRE(html.exit_code == 0);
  const html_test::Loaded page = html_test::load_in_chromium(fs::absolute(site / "index.html").string());
  const auto problems = html_test::page_problems(page, expected);
  CAPTURE(problems);
  CHECK(problems.empty());
  // Stronger than the 90 % the page checker asks: every step's equation is typeset, and the
  // prose has math of its own beyond the steps.
  const auto steps = html_test::page_steps(page.dom);
  const auto rendered = std::count_if(steps.begin(), steps.end(), [](const auto& s) { return s.rendered; });
  CHECK(static_cast<std::size_t>(rendered) == expected.size());
  CHECK(html_test::count(page.dom, "class=\"katex\"") > static_cast<int>(expected.size()));
  CHECK(expected.size() > 100);
}

TEST_CASE("every kind of mark, and the page checker catches a broken page", "[html][browser]") {
  require_chromium();
  TempDir t("marks");
  const fs::path site = t.path / "site";
  const cli_test::Run check = run({"check", "--json", src(kMarks)});
  const auto expected = html_test::checked_steps(check.out);
  const cli_test::Run html = run({"html", src(kMarks), "-o", site.string()});
  INFO(html.err);
  // a refuted step: the page is written (it shows the ✗) and the exit code is check's
  REQUIRE(html.exit_code == check.exit_code);
  REQUIRE(html.exit_code == 1);
  std::map<std::string, int> marks;
  for (const auto& e : expected) ++marks[e.mark];
  CAPTURE(marks);
  REQUIRE(marks.size() == 5);   // given, ✓, ≈, ✗, ? all occur
  const std::string index = fs::absolute(site / "index.html").string();

  SECTION("the page as written has no problem") {
    const auto problems = html_test::page_problems(html_test::load_in_chromium(index), expected);
    CAPTURE(problems);
    CHECK(problems.empty());
  }
  SECTION("a mark that differs from check is caught") {
    std::string page = slurp(index);
    const auto at = page.find("m-proved\">\u2713<", page.find("data-step="));   // a step's, not the legend's
    REQUIRE(at != std::string::npos);
    page.replace(at, std::string("m-proved\">\u2713<").size(), "m-proved\">\u2248<");
    std::ofstream(index, std::ios::binary | std::ios::trunc) << page;
    const auto problems = html_test::page_problems(html_test::load_in_chromium(index), expected);
    CAPTURE(problems);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].find("'\u2248', check") != std::string::npos);
  }
  SECTION("an equation KaTeX cannot parse is caught (console error, step not rendered)") {
    std::string page = slurp(index);
    const auto at = page.find("\\begin{aligned}");
    REQUIRE(at != std::string::npos);
    page.insert(at + std::string("\\begin{aligned}").size(), "\\undefinedmacro ");
    std::ofstream(index, std::ios::binary | std::ios::trunc) << page;
    const html_test::Loaded loaded = html_test::load_in_chromium(index);
    const auto problems = html_test::page_problems(loaded, expected);
    CAPTURE(problems);
    CHECK(std::any_of(problems.begin(), problems.end(), [](const auto& p) { return p.rfind("console:", 0) == 0; }));
    const auto steps = html_test::page_steps(loaded.dom);
    CHECK(std::count_if(steps.begin(), steps.end(), [](const auto& s) { return !s.rendered; }) == 1);
  }
  SECTION("a page without KaTeX is caught (under 90 % rendered, console errors)") {
    fs::remove(site / "katex" / "katex.min.js");
    const auto problems = html_test::page_problems(html_test::load_in_chromium(index), expected);
    CAPTURE(problems);
    CHECK(std::any_of(problems.begin(), problems.end(),
                      [](const auto& p) { return p.find("under 90 %") != std::string::npos; }));
    CHECK(std::any_of(problems.begin(), problems.end(), [](const auto& p) { return p.rfind("console:", 0) == 0; }));
  }
}

TEST_CASE("the typesetting fixture and the textbook derivations render with no console message", "[html][browser]") {
  require_chromium();
  TempDir t("typesetting");
  const fs::path site = t.path / "site";
  const std::vector<std::string> inputs = {src("tests/data/latex/typesetting.dc"), src("derivations/textbook/")};
  std::vector<std::string> args = {"check", "--json"};
  args.insert(args.end(), inputs.begin(), inputs.end());
  const auto expected = html_test::checked_steps(run(args).out);
  args = {"html"};
  args.insert(args.end(), inputs.begin(), inputs.end());
  args.insert(args.end(), {"-o", site.string()});
  REQUIRE(run(args).exit_code == 0);
  const html_test::Loaded page = html_test::load_in_chromium(fs::absolute(site / "index.html").string());
  const auto problems = html_test::page_problems(page, expected);
  CAPTURE(problems);
  CHECK(problems.empty());
  const auto steps = html_test::page_steps(page.dom);
  CHECK(std::all_of(steps.begin(), steps.end(), [](const auto& s) { return s.rendered; }));
  CHECK(steps.size() > 100);
}

TEST_CASE("byte-identical sites across runs and --jobs", "[html]") {
  TempDir t("determinism");
  const cli_test::Run a = run({"html", src("derivations/handout9/"), "-o", (t.path / "a").string(), "--jobs", "1"});
  const cli_test::Run b = run({"html", src("derivations/handout9/"), "-o", (t.path / "b").string(), "--jobs", "2"});
  REQUIRE(a.exit_code == 0);
  REQUIRE(b.exit_code == 0);
  const auto ta = tree(t.path / "a"), tb = tree(t.path / "b");
  CHECK(ta.size() > 60);   // index.html, KaTeX's script, style sheet, auto-render and its fonts
  CHECK(ta.count("index.html") == 1);
  CHECK(ta.count("katex/contrib/auto-render.js") == 1);
  CHECK(ta == tb);
  // the KaTeX copy is Debian's, byte for byte
  CHECK(ta.at("katex/katex.min.js") == slurp("/usr/share/javascript/katex/katex.min.js"));
}

TEST_CASE("figures the code draws are SVG pictures of the same data, a sketch stays a box", "[html]") {
  TempDir t("figures");
  const cli_test::Run r = run({"html", src("tests/data/latex/figures.dc"), "-o", (t.path / "site").string()});
  REQUIRE(r.exit_code == 0);
  const std::string page = slurp(t.path / "site" / "index.html");
  auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t p = page.find(what); p != std::string::npos; p = page.find(what, p + 1)) ++n;
    return n;
  };
  CHECK(count("<figure class=\"plot\"><svg class=\"plot\"") == 1);
  CHECK(count("<figure class=\"placeholder\">") == 1);
  CHECK(count("<polyline ") == 2);   // the parabola and the line, each unbroken
  // the parabola y = 1/2 + 3 x^2 over [-1, 1] reaches 3.5 at both ends: the highest tick is 3
  CHECK(page.find(">3</text>") != std::string::npos);
  CHECK(page.find(">4</text>") == std::string::npos);
  CHECK(page.find("horizontal: \\(x\\)") != std::string::npos);   // axis names typeset by KaTeX
  // the handout: Example 9.3 from the simulation and the three plots
  const cli_test::Run h = run({"html", src("derivations/handout9/"), "-o", (t.path / "h").string()});
  REQUIRE(h.exit_code == 0);
  const std::string handout = slurp(t.path / "h" / "index.html");
  std::size_t svgs = 0;
  for (std::size_t p = handout.find("<svg class=\"plot\""); p != std::string::npos;
       p = handout.find("<svg class=\"plot\"", p + 1))
    ++svgs;
  CHECK(svgs == 4);
}

TEST_CASE("bad input is a positioned error and writes nothing", "[html]") {
  TempDir t("bad");
  const fs::path bad = t.path / "bad.dc";
  std::ofstream(bad) << "symbol x : real [1]\nf: x = y\n    by given\n";
  const fs::path site = t.path / "site";
  const cli_test::Run r = run({"html", bad.string(), "-o", site.string()});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find(bad.string() + ":2:8: error:") != std::string::npos);
  CHECK_FALSE(fs::exists(site));
  // references that contradict each other are bad input too (check's exit 2): no site either
  const fs::path contra = t.path / "contra.dc";
  std::ofstream(contra) << "symbol a, x : real [1]\na1: a = 1\n    by given\na2: a = 2\n    by given\n"
                           "bad: x = 5\n    by rewrite a1, a2\n";
  const cli_test::Run c = run({"html", contra.string(), "-o", site.string()});
  CHECK(c.exit_code == 2);
  CHECK(c.err.find(contra.string() + ":7:") != std::string::npos);
  CHECK(c.err.find("contradict each other") != std::string::npos);
  CHECK_FALSE(fs::exists(site));
  // no temporary folder is left beside it either
  for (const auto& e : fs::directory_iterator(t.path)) CHECK(e.path().filename().string().rfind(".site", 0) != 0);
}

TEST_CASE("a folder it did not write is refused, its own site and an empty folder are replaced", "[html]") {
  TempDir t("clobber");
  const fs::path site = t.path / "site";
  fs::create_directories(site);
  std::ofstream(site / "notes.txt") << "a lecturer's notes\n";
  const cli_test::Run refused = run({"html", src(kMarks), "-o", site.string()});
  CHECK(refused.exit_code == 2);
  CHECK(refused.err.find("refusing to replace") != std::string::npos);
  CHECK(refused.err.find("notes.txt") != std::string::npos);
  CHECK(slurp(site / "notes.txt") == "a lecturer's notes\n");
  CHECK_FALSE(fs::exists(site / "index.html"));

  // an index.html html did not write is foreign too
  fs::remove(site / "notes.txt");
  std::ofstream(site / "index.html") << "<html>the course page</html>\n";
  CHECK(run({"html", src(kMarks), "-o", site.string()}).exit_code == 2);
  CHECK(slurp(site / "index.html") == "<html>the course page</html>\n");

  // an empty folder is filled; a second run replaces the site with the same bytes
  fs::remove(site / "index.html");
  CHECK(run({"html", src(kMarks), "-o", site.string()}).exit_code == 1);   // marks.dc has a refuted step
  const auto first = tree(site);
  CHECK(first.count("index.html") == 1);
  CHECK(run({"html", src(kMarks), "-o", site.string()}).exit_code == 1);
  CHECK(tree(site) == first);
  for (const auto& e : fs::directory_iterator(t.path)) CHECK(e.path().filename() == "site");

  // a file where the folder should be
  const fs::path file = t.path / "plain.txt";
  std::ofstream(file) << "x\n";
  const cli_test::Run on_file = run({"html", src(kMarks), "-o", file.string()});
  CHECK(on_file.exit_code == 2);
  CHECK(slurp(file) == "x\n");
}
