// libFuzzer harness: the .dc file reader alone (no GiNaC), fast enough for millions of inputs.
// The bytes are a whole derivation file as load_derivation reads it: parse_derivation (text
// normalisation: BOM, CR/CRLF, UTF-8; statements, declarations, rule lines, expressions, label
// references, symbol resolution) returns or throws InputError. For a file that parses, every
// step's claim prints (to_text) and the printed claim reads again to the same text, and every
// label a rule refers to names an earlier step. The file's text (headings, paragraphs) stands
// in file order among the steps, and the whole file prints as LaTeX without an exception.
// fuzz_dc_file continues into the GiNaC conversion
// (about 10 inputs per second instead of thousands).
#include "bench/fuzz/fuzz_common.hpp"
#include "derivations/reader/derivation.hpp"
#include "derivations/report/latex.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return 0;
  dc::SourceText src{"fuzz.dc", dc_fuzz::bytes(data, size)};
  dc::Derivation d;
  try {
    d = dc::parse_derivation(std::move(src));
  } catch (const dc::InputError& e) {
    dc_fuzz::touch(e);
    return 0;
  }
  for (std::size_t i = 0; i < d.steps.size(); ++i) {
    const dc::Step& s = d.steps[i];
    if (d.find(s.label) != &s) dc_fuzz::fail("a step's label does not find the step", s.label);
    for (const auto* group : {&s.rule.refs, &s.rule.into, &s.rule.smalls})
      for (const auto& a : *group) {
        if (a.kind != dc::RuleArg::Kind::Label) continue;
        const dc::Step* t = d.find(a.label);
        if (!t || t >= &s) dc_fuzz::fail("a rule refers to a label that is not an earlier step", s.label, a.label);
      }
    dc_fuzz::check_round_trip(dc::to_text(s.claim));
  }
  for (std::size_t i = 0; i < d.prose.size(); ++i) {
    if (d.prose[i].before_step > d.steps.size()) dc_fuzz::fail("text placed after a step that does not exist", std::to_string(d.prose[i].before_step));
    if (i && d.prose[i].before_step < d.prose[i - 1].before_step) dc_fuzz::fail("text out of file order", std::to_string(i));
    if (d.prose[i].pieces.empty()) dc_fuzz::fail("a text statement with nothing in it", std::to_string(d.prose[i].pos.line));
  }
  std::string tex = dc::write_latex(d, dc::LatexOptions{});
  if (tex.find("\\end{document}") == std::string::npos) dc_fuzz::fail("LaTeX output without its end", tex.substr(0, 200));
  return 0;
}
