// Shared by the libFuzzer harnesses: the contract they check is the one in source.hpp — an input
// problem is a dc::InputError (exit 2), anything else escaping is an internal error (exit 3) and
// is left to escape, so libFuzzer reports it (uncaught exception -> abort -> crash input saved).
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "derivations/syntax/expr.hpp"
#include "derivations/syntax/source.hpp"

namespace dc_fuzz {

inline std::string bytes(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// An InputError must be printable (the CLI prints every one with format()).
inline void touch(const dc::InputError& e) {
  std::string s = e.format();
  if (s.empty()) std::abort();
}

// A property of the code under test does not hold: print it and abort (a crash for libFuzzer).
[[noreturn]] inline void fail(const char* what, const std::string& a, const std::string& b = {}) {
  std::fprintf(stderr, "fuzz property failed: %s\n  [%s]\n  [%s]\n", what, a.c_str(), b.c_str());
  std::abort();
}

// The printer's contract: a printed tree reads back to the same text. The printed form may nest
// deeper than the original (added parentheses), so the depth limits are relaxed for the re-read.
inline void check_round_trip(const std::string& printed) {
  dc::ParseLimits relaxed;
  relaxed.max_depth = 1000;
  relaxed.max_tree_depth = 20000;
  relaxed.max_length = 1000000;
  try {
    dc::Relation again = dc::parse_relation(printed, dc::SourcePos{"<printed>", 1, 1}, relaxed);
    if (dc::to_text(again) != printed) fail("to_text(parse(to_text(r))) != to_text(r)", printed, dc::to_text(again));
  } catch (const dc::InputError& e) {
    fail("to_text(r) does not parse", printed, e.format());
  }
}

}  // namespace dc_fuzz
