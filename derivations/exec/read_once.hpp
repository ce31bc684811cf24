// Reading derivation files once, under the budget, for a command that then goes on with them.
//
// A file's reading can run away (it converts every claim, samples the assumptions, evaluates
// limits and integrals written inside expressions), and GiNaC cannot be interrupted from
// inside, so reading needs a process of its own. Reading in a worker and again in the process
// that reports parses every file twice. Instead, this process forks once: the child reads the
// files under the budget (a CPU timer and an address-space limit per file) and, when all are
// read, RETURNS them to its caller and goes on with the command (checks the steps, prints,
// exits). The parent only supervises: it never returns from read_files_once; it exits with
// the child's exit status. When a file's reading exceeds the budget (or the child dies while
// reading it), the parent forks a new child that records that file as unreadable ("reading this
// file did not finish: time budget 2 s exceeded; it was not checked") and reads the others, so
// one runaway file costs one re-read of the files before it, never the run.
//
// For the CLI only (`check`, `latex`): the calling process's remaining work moves into the
// child, which a library caller (a test inside Catch2) must not have. check_files() without
// RunOptions::read_once keeps the two-read path that returns in-process.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "derivations/exec/budget.hpp"
#include "derivations/reader/derivation.hpp"

namespace dc::exec {

struct ReadFile {
  std::optional<Derivation> derivation;
  std::optional<InputError> error;   // a reading error, or the budget it exceeded
  double seconds = 0;                // reading time (not deterministic)
};

// Returns, in the child, one entry per file in order. Flushes stdout and stderr first.
std::vector<ReadFile> read_files_once(const std::vector<std::string>& files, const Budget& budget);

}  // namespace dc::exec
