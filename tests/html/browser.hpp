// What a real browser makes of a page `derivcheck html` wrote: headless Chromium (Debian
// `chromium`) loads index.html from file://, runs KaTeX, and dumps the DOM; its console
// messages come on stderr (--enable-logging=stderr). page_problems() compares the rendered
// page with `check --json`, step by step.
#pragma once
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_run.hpp"

namespace html_test {

inline bool have_chromium() { return std::system("command -v chromium > /dev/null 2>&1") == 0; }

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Loaded {
  int exit_code = -1;
  std::string dom;                     // the DOM after the page's scripts ran
  std::vector<std::string> console;    // every console message of the page (errors, warnings, logs)
};

// Loads `index` (an absolute path) in headless Chromium. The page itself logs nothing, so any
// console message (a script error, a resource that failed to load, a KaTeX parse error or
// warning) is a problem; Chromium prints every level as "INFO:CONSOLE", hence all are kept.
inline Loaded load_in_chromium(const std::string& index) {
  const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(std::rand());
  const auto tmp = std::filesystem::temp_directory_path();
  const std::string dom_file = (tmp / ("dc_html_dom_" + tag + ".html")).string();
  const std::string err_file = (tmp / ("dc_html_err_" + tag + ".txt")).string();
  const std::string profile = (tmp / ("dc_html_profile_" + tag)).string();
  const std::string cmd = "timeout 120 chromium --headless --disable-gpu --no-sandbox --no-first-run "
                          "--user-data-dir=" + cli_test::quote(profile) +
                          " --enable-logging=stderr --v=0 --virtual-time-budget=10000 --dump-dom " +
                          cli_test::quote("file://" + index) + " > " + cli_test::quote(dom_file) + " 2> " +
                          cli_test::quote(err_file);
  Loaded l;
  const int status = std::system(cmd.c_str());
  l.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  l.dom = slurp(dom_file);
  for (const auto& line : cli_test::lines_of(slurp(err_file)))
    if (line.find(":CONSOLE") != std::string::npos) l.console.push_back(line);
  std::error_code ec;
  std::filesystem::remove(dom_file, ec);
  std::filesystem::remove(err_file, ec);
  std::filesystem::remove_all(profile, ec);
  return l;
}

inline int count(const std::string& hay, const std::string& needle) {
  int n = 0;
  for (auto at = hay.find(needle); at != std::string::npos; at = hay.find(needle, at + needle.size())) ++n;
  return n;
}

inline std::string attribute(const std::string& tag, const std::string& name) {
  const auto at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return {};
  const auto from = at + name.size() + 3;
  return tag.substr(from, tag.find('"', from) - from);
}

// One step as the browser shows it.
struct PageStep {
  std::string step;      // data-step: "file.dc:label"
  std::string verdict;   // data-verdict
  std::string mark;      // the visible mark's text
  bool rendered = false; // its equation holds a KaTeX node
};

inline std::vector<PageStep> page_steps(const std::string& dom) {
  std::vector<PageStep> out;
  const std::string open = "<div class=\"step\"";
  for (auto at = dom.find(open); at != std::string::npos; at = dom.find(open, at + 1)) {
    const auto next = dom.find(open, at + 1);
    const std::string block = dom.substr(at, next == std::string::npos ? std::string::npos : next - at);
    PageStep s;
    const std::string tag = block.substr(0, block.find('>'));
    s.step = attribute(tag, "data-step");
    s.verdict = attribute(tag, "data-verdict");
    // KaTeX writes spans (and svg), never a div: the equation's div ends at the first </div>
    const auto eq = block.find("<div class=\"eq\">");
    if (eq != std::string::npos) {
      const std::string math = block.substr(eq, block.find("</div>", eq) - eq);
      s.rendered = math.find("class=\"katex\"") != std::string::npos;
    }
    const auto mark = block.find("<span class=\"mark ");
    if (mark != std::string::npos) {
      const auto text = block.find('>', mark) + 1;
      s.mark = block.substr(text, block.find("</span>", text) - text);
    }
    out.push_back(s);
  }
  return out;
}

// A step as `check --json` reports it, with the mark the page must show for it.
struct CheckedStep {
  std::string step, verdict, mark;
};

inline std::vector<CheckedStep> checked_steps(const std::string& check_json) {
  std::vector<CheckedStep> out;
  const auto j = nlohmann::json::parse(check_json);
  for (const auto& f : j.at("files")) {
    std::string file = f.at("file").get<std::string>();
    file = file.substr(file.find_last_of('/') + 1);
    for (const auto& s : f.at("steps")) {
      CheckedStep c;
      c.step = file + ":" + s.at("label").get<std::string>();
      c.verdict = s.at("verdict").get<std::string>();
      const std::size_t own = s.at("errors").size() - (s.at("erratum_reported").get<bool>() ? 1 : 0);
      c.mark = own > 0                           ? "\u2717"
               : c.verdict == "premise"           ? "given"
               : c.verdict == "proved"            ? "\u2713"
               : c.verdict == "holds_numerically" ? "\u2248"
               : c.verdict == "refuted"           ? "\u2717"
                                                  : "?";
      out.push_back(c);
    }
  }
  return out;
}

// Everything wrong with a loaded page against `check --json`: console messages, KaTeX errors,
// fewer than 90 % of the steps rendered, and any step whose place, verdict or mark differs.
inline std::vector<std::string> page_problems(const Loaded& page, const std::vector<CheckedStep>& expected) {
  std::vector<std::string> problems;
  if (page.exit_code != 0) problems.push_back("chromium exited with " + std::to_string(page.exit_code));
  for (const auto& c : page.console) problems.push_back("console: " + c);
  if (const int e = count(page.dom, "katex-error")) problems.push_back(std::to_string(e) + " KaTeX error nodes");
  const std::vector<PageStep> steps = page_steps(page.dom);
  const auto rendered = std::count_if(steps.begin(), steps.end(), [](const PageStep& s) { return s.rendered; });
  if (10 * rendered < 9 * static_cast<long>(expected.size()))
    problems.push_back("math rendered for " + std::to_string(rendered) + " of " + std::to_string(expected.size()) +
                       " steps (under 90 %)");
  if (steps.size() != expected.size())
    problems.push_back("the page has " + std::to_string(steps.size()) + " steps, check --json " +
                       std::to_string(expected.size()));
  for (std::size_t i = 0; i < std::min(steps.size(), expected.size()); ++i) {
    const PageStep& p = steps[i];
    const CheckedStep& c = expected[i];
    if (p.step != c.step || p.verdict != c.verdict || p.mark != c.mark)
      problems.push_back("step " + std::to_string(i + 1) + ": page " + p.step + " " + p.verdict + " '" + p.mark +
                         "', check " + c.step + " " + c.verdict + " '" + c.mark + "'");
  }
  return problems;
}

}  // namespace html_test
