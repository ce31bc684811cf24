// The `vector` declaration (docs/format.md, "Vectors"):
//
//   vector F, a : 3 [N]                          components F_x, F_y, F_z and a_x, a_y, a_z
//   vector v1 : 2 [m/s] components v1n, v1t      components named by the author
//   vector r(t) : 3 [m]                          a vector function: r_x(t), r_y(t), r_z(t)
//   vector p : 3 [kg*m/s] tex "\vec{p}"
//
// A component name that is already a symbol of the vector's unit is that symbol (the author
// wrote the components first); any other clash is an input error.
// Each component is declared as a real symbol (a function of the same arguments for a vector
// function) with the vector's unit; the vector itself is a table entry that only the vector
// rewriting reads (symbolic/vectors.hpp).
#include "derivations/reader/internal/dc_reader.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/symbolic/vectors.hpp"
#include "derivations/syntax/units.hpp"

namespace dc::reader_detail {

// \mathbf{r}_{0} for r0: the decoration on the base of the name, not on its subscript.
std::string vector_tex(const std::string& command, const std::string& name) {
  const std::string tex = default_tex_name(name);
  const std::size_t us = tex.find('_');
  return command + "{" + tex.substr(0, us) + "}" + (us == std::string::npos ? "" : tex.substr(us));
}

void DcReader::vector_statement(const Span& s) {
  std::size_t p = 0;
  struct NameAt {
    std::string name;
    SourcePos pos;
  };
  std::vector<NameAt> names;
  std::vector<std::string> params;
  for (;;) {
    skip_ws(s, p);
    SourcePos np = s.at(p);
    names.push_back({identifier(s, p, "a vector name, e.g. 'vector F, a : 3 [N]'"), np});
    skip_ws(s, p);
    if (p < s.text.size() && s.text[p] == '(') {   // a vector function r(t)
      if (names.size() > 1) fail(s.at(p), "a vector function is declared on its own: 'vector r(t) : 3 [m]'");
      ++p;
      params = parameters(s, p, names[0].name);
      skip_ws(s, p);
      break;
    }
    if (p < s.text.size() && s.text[p] == ',') { ++p; continue; }
    break;
  }
  for (const auto& n : names)
    if (is_reserved_name(n.name) || contains(kRuleKeywords, n.name) || n.name == "by" || n.name == "deg")
      fail(n.pos, "'" + n.name + "' is a reserved name and cannot be declared as a vector", static_cast<int>(n.name.size()));
  if (p >= s.text.size() || s.text[p] != ':')
    fail(s.at(p), "expected ':' and the number of components after the vector names, e.g. ': 3 [m/s]'");
  ++p;
  skip_ws(s, p);
  const SourcePos dim_pos = s.at(p);
  std::size_t de = p;
  while (de < s.text.size() && !is_space(s.text[de]) && s.text[de] != '[') ++de;
  const std::string dim_text = s.text.substr(p, de - p);
  if (dim_text != "2" && dim_text != "3")
    fail(dim_pos, "expected the number of components, 2 or 3, found '" + dim_text + "'",
         static_cast<int>(std::max<std::size_t>(1, dim_text.size())));
  const int dim = dim_text[0] - '0';
  p = de;
  skip_ws(s, p);
  if (p >= s.text.size() || s.text[p] != '[')
    fail(s.at(p), "expected the unit in brackets after the number of components, e.g. [m/s] or [1]");
  const std::size_t close = s.text.find(']', p);
  if (close == std::string::npos) fail(s.at(p), "expected ']' to close the unit");
  Node unit = expression(s, p + 1, close, "a unit inside '[ ]', e.g. [kg*m/s^2] or [1]");
  const Dimension dimension = parse_dimension(unit);
  p = close + 1;
  std::vector<std::string> tex;
  std::vector<NameAt> components;
  for (;;) {
    skip_ws(s, p);
    if (p >= s.text.size()) break;
    std::size_t we;
    const SourcePos wpos = s.at(p);
    const std::string w = word_at(s.text, p, &we);
    if (w == "tex" && tex.empty()) {
      p = we;
      for (;;) {
        tex.push_back(string_literal(s, p, "a quoted TeX name, e.g. tex \"\\vec{F}\""));
        skip_ws(s, p);
        if (p < s.text.size() && s.text[p] == ',') { ++p; continue; }
        break;
      }
      if (tex.size() != names.size())
        fail(wpos, "expected " + std::to_string(names.size()) + " TeX name" + (names.size() == 1 ? "" : "s") +
                       " (one per vector), found " + std::to_string(tex.size()), 3);
    } else if (w == "components" && components.empty()) {
      if (names.size() != 1) fail(wpos, "'components' names those of one vector: declare it on its own", 10);
      p = we;
      for (;;) {
        skip_ws(s, p);
        SourcePos cp = s.at(p);
        components.push_back({identifier(s, p, "a component name"), cp});
        skip_ws(s, p);
        if (p < s.text.size() && s.text[p] == ',') { ++p; continue; }
        break;
      }
      if (static_cast<int>(components.size()) != dim)
        fail(wpos, "expected " + std::to_string(dim) + " component names, found " + std::to_string(components.size()), 10);
    } else {
      fail(wpos, "unexpected text '" + excerpt(s, p) + "'; expected 'tex \"...\"', 'components a, b[, c]' or the end");
    }
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::vector<NameAt> parts = components;
    if (parts.empty())
      for (const auto& c : default_component_names(names[i].name, dim)) parts.push_back({c, names[i].pos});
    SymbolInfo v;
    v.name = names[i].name;
    v.tex = tex.empty() ? vector_tex("\\mathbf", names[i].name) : tex[i];
    if (tex.empty()) default_vector_tex_.push_back(v.name);
    v.dimension = dimension;
    v.has_dimension = true;
    if (unit_as_written(unit)) v.unit = to_text(unit);
    v.pos = names[i].pos;
    v.is_function = !params.empty();
    v.params = params;
    v.vector_dim = dim;
    for (const auto& c : parts) v.components.push_back(c.name);
    d_.symbols.declare(v);
    for (const auto& c : parts) {
      // a component already declared as a quantity of the vector's unit (symbol v1np : real
      // [m/s], then vector v1p : 2 [m/s] components v1np, v1tp) is adopted as it is
      if (const SymbolInfo* old = d_.symbols.find(c.name);
          old && !old->vector_dim && !old->is_differential && old->is_function == v.is_function &&
          old->params == params && old->has_dimension && old->dimension == dimension)
        continue;
      if (is_reserved_name(c.name) || d_.symbols.find(c.name))
        fail(c.pos, "the component '" + c.name + "' of vector '" + v.name + "' is already a name of another kind or unit; " +
                        "name the components: 'vector " + v.name + " : " + std::to_string(dim) + " [...] components a, b" +
                        (dim == 3 ? ", c'" : "'"),
             static_cast<int>(v.name.size()));
      SymbolInfo ci;
      ci.name = c.name;
      ci.dimension = dimension;
      ci.has_dimension = true;
      ci.unit = v.unit;
      ci.pos = c.pos;
      ci.is_function = v.is_function;
      ci.params = params;
      d_.symbols.declare(std::move(ci));
    }
  }
}

}  // namespace dc::reader_detail
