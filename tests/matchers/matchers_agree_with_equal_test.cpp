// A matcher and `derivcheck equal` (a claim bank's `equal` line) decide one claim the same way:
// every `equal` claim of the labelled corpora whose sides GiNaC's own parser reads is matched
// with GiNaC expressions (the way a user's test holds them) and with strings, and each verdict
// must be the bank's.
#include <catch2/catch.hpp>

#include <fstream>
#include <functional>
#include <set>
#include <string>

#include <ginac/ginac.h>
#include <nlohmann/json.hpp>

#include "derivations/catch/derivcheck_catch.hpp"
#include "derivations/claims/claims.hpp"

namespace {

// "m1 positive, e in [0, 1], v1 > v2": the line's domains, then its own "assume" field.
std::string assumption_text(const nlohmann::json& j) {
  std::string out;
  if (j.contains("assumptions") && j.at("assumptions").is_object())
    for (const auto& [name, dom] : j.at("assumptions").items())
      out += (out.empty() ? "" : ", ") + name + " " + dom.get<std::string>();
  if (j.contains("assume") && j.at("assume").is_string() && !j.at("assume").get<std::string>().empty())
    out += (out.empty() ? "" : ", ") + j.at("assume").get<std::string>();
  return out;
}

// The side as GiNaC reads it with the symbols of `syms`, or false when GiNaC's parser does not
// know a function of it (limit, integral, ln, ...).
bool ginac_side(const std::string& text, GiNaC::symtab& syms, GiNaC::ex& out) {
  if (text.find("pi") != std::string::npos || text.find("ln(") != std::string::npos ||
      text.find("oo") != std::string::npos || text.find("Euler") != std::string::npos)
    return false;
  try {
    GiNaC::parser reader(syms);
    out = reader(text);
    syms = reader.get_syms();
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

// GiNaC evaluates while it builds: its parser turns exp(log(x)) into x, and reads `deg` as a
// plain symbol. Such an expression is not the claim as written, and a matcher given it decides
// what it holds; the comparison is made only where GiNaC's expression is the one derivcheck
// reads from the text (the same tree, term by term).
bool same_as_written(const std::string& lhs, const GiNaC::ex& l, const std::string& rhs, const GiNaC::ex& r,
                     const std::string& assume) {
  try {
    const dc::Node nl = dc::parse_expression(lhs, dc::SourcePos{"<lhs>", 1, 1});
    const dc::Node nr = dc::parse_expression(rhs, dc::SourcePos{"<rhs>", 1, 1});
    const dc::SymbolTable table = dc::catch2::detail::table_for({&nl, &nr}, assume);
    GiNaC::exmap by_name;
    for (const GiNaC::ex* e : {&l, &r})
      for (GiNaC::const_preorder_iterator it = e->preorder_begin(); it != e->preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) {
          const dc::SymbolInfo* info = table.find(GiNaC::ex_to<GiNaC::symbol>(*it).get_name());
          if (!info) return false;
          by_name[*it] = info->sym;
        }
    if (!(dc::to_ginac(nl, table) - l.subs(by_name)).is_zero() || !(dc::to_ginac(nr, table) - r.subs(by_name)).is_zero())
      return false;
    // the functions written must survive too: exp(log(x)) is x for GiNaC and for derivcheck,
    // but derivcheck's reading of the text keeps the log's condition x > 0
    const auto calls = [](const dc::Node& n) {
      std::multiset<std::string> out;
      std::function<void(const dc::Node&)> walk = [&](const dc::Node& m) {
        if (m.kind == dc::NodeKind::Call) out.insert(m.text);
        for (const auto& a : m.args) walk(a);
      };
      walk(n);
      return out;
    };
    const auto reprinted = [&](const GiNaC::ex& e) {
      return dc::parse_expression(dc::print_text(e.subs(by_name), table), dc::SourcePos{"<printed>", 1, 1});
    };
    return calls(nl) == calls(reprinted(l)) && calls(nr) == calls(reprinted(r));
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

TEST_CASE("matchers: every corpus equal-claim gets the bank's verdict, as expressions and as strings",
          "[matchers][claims]") {
  int compared = 0;
  for (const char* file : {"tests/data/corpus.jsonl", "tests/data/adversarial.jsonl"}) {
    std::ifstream in(std::string(DERIVCHECK_SOURCE_DIR) + "/" + file);
    REQUIRE(in);
    std::string line;
    int line_no = 0;
    while (std::getline(in, line)) {
      ++line_no;
      if (line.empty()) continue;
      const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
      if (j.is_discarded() || j.value("kind", "equal") != "equal") continue;
      const std::string assume = assumption_text(j);
      if (assume.find("integer") != std::string::npos) continue;   // `--assume` has no integer domain
      const auto bank = dc::check_claim_line(line, line_no, file);
      if (bank.value("verdict", "") == "error") continue;
      const std::string lhs = j.at("lhs").get<std::string>(), rhs = j.at("rhs").get<std::string>();
      CAPTURE(file, line_no, lhs, rhs, assume, bank.dump());

      auto by_strings = dc::catch2::EqualsSymbolically(rhs).assuming(assume);
      (void)by_strings.match(lhs);
      REQUIRE(by_strings.verdict() != nullptr);
      CHECK(dc::to_string(by_strings.verdict()->kind) == bank.at("verdict").get<std::string>());

      GiNaC::symtab syms;
      GiNaC::ex l, r;
      if (!ginac_side(lhs, syms, l) || !ginac_side(rhs, syms, r)) continue;
      if (!same_as_written(lhs, l, rhs, r, assume)) continue;
      auto by_expressions = dc::catch2::EqualsSymbolically(r).assuming(assume);
      (void)by_expressions.match(l);
      REQUIRE(by_expressions.verdict() != nullptr);
      CHECK(dc::to_string(by_expressions.verdict()->kind) == bank.at("verdict").get<std::string>());
      ++compared;
    }
  }
  // the corpora hold about 270 equal-claims; most have sides GiNaC's parser reads
  CHECK(compared >= 150);
}
