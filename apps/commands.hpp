// Subcommands of the derivcheck CLI. Each apps/cmd_*.cpp registers itself with a static
// CommandRegistrar; main() builds the CLI11 app from the registry. All logic lives in the
// libraries; a command only parses its options and prints.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "derivations/symbolic/verdict.hpp"

namespace dc::cli {

// setup adds the subcommand's options to `sub` and returns the function that runs it
// (returning the process exit code).
using Setup = std::function<std::function<int()>(CLI::App& sub)>;

struct Command {
  std::string name;
  std::string help;
  Setup setup;
};

std::vector<Command>& registry();

struct CommandRegistrar {
  CommandRegistrar(std::string name, std::string help, Setup setup) {
    registry().push_back({std::move(name), std::move(help), std::move(setup)});
  }
};

// Exit codes: defined once, with the verdicts (derivations/symbolic/verdict.hpp).
using dc::kExitOk;
using dc::kExitRefuted;
using dc::kExitInputError;
using dc::kExitUndecided;
using dc::kExitInternal;

}  // namespace dc::cli
