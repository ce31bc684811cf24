// derivcheck — checks derivations step by step. Thin CLI over the libraries.
#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>

#include "apps/commands.hpp"
#include "derivations/core/source.hpp"

namespace dc::cli {
std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}
}  // namespace dc::cli

int main(int argc, char** argv) {
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
    app.parse(argc, argv);
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
