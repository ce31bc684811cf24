// The seed handout (../shared/handout9.md), checked as its author wrote it: every displayed
// relation is read, nothing true is refuted, the one undefined name (v_e) is reported as a
// warning, and a slip planted in a derived row is refuted at that row.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>
#include <vector>

#include "cli/cli_run.hpp"

namespace {

std::string seed_path() { return cli_test::src("../shared/handout9.md"); }

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Counts {
  int rows = 0, derived = 0, given = 0, refuted = 0, undecided = 0;
};

Counts counts(const nlohmann::json& j) {
  Counts c;
  for (const auto& f : j["files"])
    for (const auto& s : f["steps"]) {
      ++c.rows;
      const std::string v = s["verdict"];
      if (v == "proved" || v == "holds_numerically") ++c.derived;
      else if (v == "premise") ++c.given;
      else if (v == "refuted") ++c.refuted;
      else ++c.undecided;
    }
  return c;
}

}  // namespace

TEST_CASE("seed handout: checked as written, nothing refuted, v_e reported") {
  const std::string path = seed_path();
  REQUIRE(std::ifstream(path).good());
  cli_test::Run r = cli_test::run({"check", "--json", path});
  REQUIRE(r.err.empty());
  const auto j = nlohmann::json::parse(r.out);
  const Counts c = counts(j);
  INFO("rows " << c.rows << ", derived " << c.derived << ", given " << c.given << ", refuted " << c.refuted
               << ", undecided " << c.undecided);
  CHECK(c.refuted == 0);
  CHECK(c.rows >= 80);
  CHECK(c.derived >= 41);   // measured 41 (docs/documents.md); the issue asks for 40
  bool v_e = false;
  for (const auto& f : j["files"])
    if (f.contains("diagnostics"))
      for (const auto& d : f["diagnostics"]) v_e = v_e || d["message"].get<std::string>().find("v_e") != std::string::npos;
  CHECK(v_e);
  // every row at the author's line: the line holds the row's math
  const std::string text = read_all(path);
  std::vector<std::string> lines = cli_test::lines_of(text);
  for (const auto& f : j["files"])
    for (const auto& s : f["steps"]) {
      const int line = s["line"];
      REQUIRE(line >= 1);
      REQUIRE(line <= static_cast<int>(lines.size()));
      CHECK(lines[static_cast<std::size_t>(line - 1)].find('$') != std::string::npos);
    }
}

namespace {

// The seed with `right` replaced by `wrong`, checked: its report, the exit code, and the line
// and column of the change.
struct Planted {
  nlohmann::json report;
  int exit_code = 0, line = 0;
  long col = 0;
};

Planted check_planted(const std::string& right, const std::string& wrong) {
  std::string text = read_all(seed_path());
  const std::size_t at = text.find(right);
  REQUIRE(at != std::string::npos);
  text.replace(at, right.size(), wrong);
  Planted p;
  p.line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  p.col = static_cast<long>(at - text.rfind('\n', at));
  const std::string tmp = "seed_slip_" + std::to_string(::getpid()) + ".md";
  {
    std::ofstream out(tmp);
    out << text;
  }
  cli_test::Run r = cli_test::run({"check", "--json", tmp});
  std::remove(tmp.c_str());
  p.report = nlohmann::json::parse(r.out);
  p.exit_code = r.exit_code;
  return p;
}

}  // namespace

TEST_CASE("seed handout: a slip planted in a derived row is refuted at that row") {
  // the elastic velocity after impact (2 m_2 v_2 made m_2 v_2), the general impact velocity
  // (+ m_2 v_2 made - m_2 v_2), the integrated rocket equation (-u_e made +u_e)
  const std::vector<std::pair<std::string, std::string>> slips = {
      {"v'_1 = \\frac{(m_1 - m_2) v_1 + 2m_2 v_2}{m_1 + m_2}", "v'_1 = \\frac{(m_1 - m_2) v_1 + m_2 v_2}{m_1 + m_2}"},
      {"\\frac{m_1 v_1 + m_2 v_2 - e m_2 (v_1 - v_2)}{m_1 + m_2}", "\\frac{m_1 v_1 - m_2 v_2 - e m_2 (v_1 - v_2)}{m_1 + m_2}"},
      {"v = -u_e \\ln \\left(\\frac{m_r}{m_0} \\right) - gt", "v = u_e \\ln \\left(\\frac{m_r}{m_0} \\right) - gt"}};
  for (const auto& [right, wrong] : slips) {
    INFO(wrong);
    const Planted p = check_planted(right, wrong);
    bool refuted_there = false;
    for (const auto& f : p.report["files"])
      for (const auto& s : f["steps"])
        if (s["verdict"] == "refuted") refuted_there = refuted_there || s["line"] == p.line;
    CHECK(refuted_there);
    CHECK(p.exit_code == 1);
  }
}

// The handout defines the thrust as F = m_r a for a rocket in free space and later writes
// F - D - m_r g cos(theta) = m_r a beside it: together the givens force m_r g = 0, and before
// that pin was caught (docs/soundness.md, "a product that is zero") each slip below "followed".
TEST_CASE("seed handout: a slip in the ideal rocket's display is never proved, though its givens pin m_r g = 0") {
  const std::vector<std::pair<std::string, std::string>> slips = {
      {"m_r a &= u_e \\mu - m_r g", "m_r a &= u_e \\mu + m_r g"},
      {"m_r \\frac{dv}{dt} &= -u_e \\frac{dm_r}{dt} - m_r g", "m_r \\frac{dv}{dt} &= +u_e \\frac{dm_r}{dt} - m_r g"},
      {"dv &= -u_e \\frac{dm_r}{m_r} - g dt", "dv &= +u_e \\frac{dm_r}{m_r} - g dt"}};
  for (const auto& [right, wrong] : slips) {
    INFO(wrong);
    const Planted p = check_planted(right, wrong);
    bool seen = false;
    for (const auto& f : p.report["files"])
      for (const auto& s : f["steps"])
        if (s["line"] == p.line && s["col"].get<long>() == p.col) {
          seen = true;
          INFO(s.dump());
          CHECK(s["verdict"] != "proved");
          CHECK(s["verdict"] != "holds_numerically");
        }
    CHECK(seen);
  }
}

TEST_CASE("annotate: the author's LaTeX with a note after each display, and it compiles") {
  const std::string dir = "annotate_test_" + std::to_string(::getpid());
  REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
  const std::string out = dir + "/projectile.checked.tex";
  cli_test::Run r = cli_test::run({"annotate", cli_test::src("tests/data/documents/projectile.tex"), "-o", out});
  CHECK(r.err.empty());
  const std::string original = read_all(cli_test::src("tests/data/documents/projectile.tex"));
  const std::string annotated = read_all(out);
  // unchanged except for the notes: removing them gives the author's text back
  std::string stripped;
  for (const auto& line : cli_test::lines_of(annotated))
    if (line.rfind("\\par\\noindent{\\footnotesize\\textsf{derivcheck:}", 0) != 0) stripped += line + "\n";
  std::string original_lines;
  for (const auto& line : cli_test::lines_of(original)) original_lines += line + "\n";
  CHECK(stripped == original_lines);
  CHECK(annotated.find("derivcheck:} line 43: derived") != std::string::npos);
  const int rc = std::system(("cd " + dir + " && pdflatex -interaction=nonstopmode -halt-on-error "
                              "projectile.checked.tex > /dev/null 2>&1").c_str());
  CHECK(rc == 0);
  std::system(("rm -rf " + dir).c_str());
}

TEST_CASE("dc: the document as a .dc file that checks to the same verdicts") {
  const std::string dir = "dc_test_" + std::to_string(::getpid());
  REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
  for (const std::string doc : {std::string("../shared/handout9.md"), std::string("tests/data/documents/projectile.tex")}) {
    INFO(doc);
    const std::string out = dir + "/doc.dc";
    cli_test::Run made = cli_test::run({"dc", cli_test::src(doc), "-o", out});
    CHECK(made.err.empty());
    cli_test::Run d = cli_test::run({"check", "--json", cli_test::src(doc)});
    cli_test::Run c = cli_test::run({"check", "--json", out});
    REQUIRE(c.exit_code != 2);   // the .dc file reads
    const auto dj = nlohmann::json::parse(d.out);
    const auto cj = nlohmann::json::parse(c.out);
    std::map<std::string, std::string> verdict;   // .dc label -> verdict in the document
    for (const auto& f : dj["files"])
      for (const auto& s : f["steps"]) {
        std::string label = s["label"];
        std::replace(label.begin(), label.end(), '.', '_');
        verdict[label] = s["verdict"];
      }
    int proved = 0;
    for (const auto& f : cj["files"])
      for (const auto& s : f["steps"]) {
        const std::string label = s["label"];
        INFO(label);
        REQUIRE(verdict.count(label));
        const std::string was = verdict[label];
        const std::string now = s["verdict"];
        // a derived row keeps its verdict (first order: a premise, noted), a refuted one stays
        // refuted, a row with no justification becomes a premise marked TODO
        if (was == "proved" && now != "proved") CHECK(s["method"] == "given");
        if (was == "refuted" && now != "refuted") CHECK(s["method"] == "given");   // a TODO note says why
        if (was == "premise") CHECK(now == "premise");
        if (was == "undecided") CHECK(now == "premise");
        proved += now == "proved";
      }
    // (projectile.tex had 10: the integral of v_y and the path "followed" with t = 0, a factor
    // of a zero product, until such proofs were caught; docs/soundness.md)
    CHECK(proved >= 9);
  }
  std::system(("rm -rf " + dir).c_str());
}
