// derivcheck — checks derivations step by step. Thin CLI over the libraries.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>

#include "apps/commands.hpp"
#include "derivations/syntax/source.hpp"
#include "derivations/calculus/install.hpp"

namespace dc::cli {
std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}

namespace {

// Expressions may start with a minus (`derivcheck equal x -x`): an argument that begins with
// '-' but is not an option of the chosen subcommand, nor the value of the option before it,
// is a positional argument. Such arguments are moved after a "--" at the end (their order
// among the positionals is kept), which is how CLI11 takes positionals that look like options.
std::vector<std::string> positional_minus(CLI::App& app, int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return args;
  CLI::App* sub = nullptr;
  try {
    sub = app.get_subcommand(args[0]);
  } catch (const CLI::OptionNotFound&) {
    return args;
  }
  std::vector<std::string> out{args[0]}, moved;
  bool plain = false;   // after a "--" given by the user
  std::string positionals_before;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& t = args[i];
    if (plain || t == "--") {
      plain = true;
      if (t != "--" || !moved.empty()) moved.push_back(t);
      continue;
    }
    if (t.size() < 2 || t[0] != '-') {
      // A positional: any minus-led positionals before it must keep their place.
      if (!moved.empty()) moved.push_back(t);
      else out.push_back(t);
      continue;
    }
    std::string name = t.substr(0, t.find('='));
    const CLI::Option* opt = sub->get_option_no_throw(name);
    if (opt == nullptr && t.rfind("--", 0) != 0 && t.size() > 2)   // -j2: a short option with its value
      opt = sub->get_option_no_throw(t.substr(0, 2));
    bool is_help = name == "-h" || name == "--help";
    if (opt == nullptr && !is_help && t.rfind("--", 0) == 0) throw CLI::ExtrasError({t});   // an unknown --flag
    if (opt == nullptr && !is_help) {
      moved.push_back(t);
      continue;
    }
    out.push_back(t);
    bool takes_value = opt != nullptr && opt->get_expected_min() > 0 && t.find('=') == std::string::npos &&
                       (t.rfind("--", 0) == 0 || t.size() == 2);
    if (takes_value && i + 1 < args.size()) out.push_back(args[++i]);
  }
  if (!moved.empty()) {
    out.push_back("--");
    out.insert(out.end(), moved.begin(), moved.end());
  }
  return out;
}

}  // namespace

}  // namespace dc::cli

namespace {

int run_command(int argc, char** argv) {
  dc::calculus::install();
  using namespace dc::cli;
  CLI::App app{"derivcheck: checks physics derivations step by step (symbolic, numeric, LaTeX)", "derivcheck"};
  app.set_version_flag("--version", std::string("derivcheck ") + DERIVCHECK_VERSION);
  app.require_subcommand(1);
  auto& cmds = registry();
  std::sort(cmds.begin(), cmds.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  std::map<CLI::App*, std::function<int()>> runners;
  for (auto& c : cmds) {
    CLI::App* sub = app.add_subcommand(c.name, c.help);
    runners[sub] = c.setup(*sub);
  }
  try {
    std::vector<std::string> args = positional_minus(app, argc, argv);
    std::reverse(args.begin(), args.end());   // CLI11 takes them in reverse order
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    int rc = app.exit(e);
    return rc == 0 ? 0 : kExitInputError;
  }
  try {
    for (auto& [sub, run] : runners)
      if (sub->parsed()) return run();
    return kExitInputError;
  } catch (const dc::InputError& e) {
    std::cerr << e.format();
    return kExitInputError;
  } catch (const std::domain_error& e) {
    std::cerr << "derivcheck: error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const std::invalid_argument& e) {
    std::cerr << "derivcheck: error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "derivcheck: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int rc = run_command(argc, argv);
  // Every output is written and closed by now (files through write_file_atomic). Leaving with
  // _exit skips the destructors of GiNaC's, CLN's and our static objects, which took about a
  // seventh of a small file's check; the sanitizer build returns normally so that LeakSanitizer
  // still runs at exit.
#ifdef DERIVCHECK_SANITIZER
  return rc;
#else
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  _exit(rc);
#endif
}
