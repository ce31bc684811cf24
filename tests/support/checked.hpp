// A .dc text parsed and checked, its results looked up by label: the fixture of the tests that
// state a derivation inline.
#pragma once
#include <catch2/catch.hpp>

#include <string>

#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"

namespace test_support {

struct Checked {
  dc::Derivation d;
  dc::CheckSummary sum;
  const dc::StepResult& at(const std::string& label) const {
    for (std::size_t i = 0; i < d.steps.size(); ++i)
      if (d.steps[i].label == label) return sum.results.at(i);
    FAIL("no step " << label);
    return sum.results.at(0);
  }
  dc::VerdictKind kind(const std::string& label) const { return at(label).verdict.kind; }
  // Does the step report an error whose message contains `part`?
  bool has_error(const std::string& label, const std::string& part) const {
    for (const auto& e : at(label).errors)
      if (e.message().find(part) != std::string::npos) return true;
    return false;
  }
};

inline Checked check_text(const std::string& body, const std::string& file = "inline.dc") {
  Checked c{dc::parse_derivation(dc::SourceText{file, body}), {}};
  c.sum = dc::check_derivation(c.d);
  return c;
}

}  // namespace test_support
