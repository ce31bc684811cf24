// The tables of the TeX math reader: Greek letters, functions, relations, spacing commands,
// connecting words and unit text.
#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "derivations/syntax/tex/internal/tokens.hpp"

namespace dc::tex {
namespace {

template <std::size_t N>
bool in(const std::array<std::string_view, N>& table, std::string_view s) {
  return std::find(table.begin(), table.end(), s) != table.end();
}

// A table looked up often (every control sequence): hashed once.
template <std::size_t N>
bool in_hashed(const std::array<std::string_view, N>& table, std::string_view s) {
  static const std::unordered_set<std::string_view> set(table.begin(), table.end());
  return set.count(s) > 0;
}

constexpr std::array<std::string_view, 48> kGreek = {
    "alpha", "beta",    "gamma", "delta",  "epsilon", "varepsilon", "zeta",   "eta",     "theta",  "vartheta",
    "iota",  "kappa",   "lambda", "mu",    "nu",      "xi",         "rho",    "varrho",  "sigma",  "varsigma",
    "tau",   "upsilon", "phi",   "varphi", "chi",     "psi",        "omega",  "Gamma",   "Delta",  "Theta",
    "Lambda", "Xi",     "Sigma", "Upsilon", "Phi",    "Psi",        "Omega",  "ell",     "hbar",   "Pi",
    "varpi", "digamma", "aleph", "imath",  "jmath",   "wp",         "partial_", "nabla_"};

constexpr std::array<std::string_view, 20> kIgnored = {
    ",", ";", ":", "!", " ", "displaystyle", "textstyle", "scriptstyle", "nonumber", "notag", "limits", "nolimits",
    "mathstrut", "strut", "ensuremath", "relax", "allowbreak", "displaybreak", "nobreak", "medspace"};

constexpr std::array<std::string_view, 16> kSizes = {"big",  "Big",  "bigg",  "Bigg",  "bigl", "Bigl", "biggl", "Biggl",
                                                     "bigr", "Bigr", "biggr", "Biggr", "bigm", "Bigm", "biggm", "Biggm"};

constexpr std::array<std::string_view, 42> kWords = {
    "by", "from", "in", "on", "of", "to", "is", "are", "we", "let", "implies", "or else",
    "and", "or",     "where", "with",      "for",   "if",      "since",    "hence", "so",  "thus",
    "then", "i.e.",  "e.g.",  "therefore", "gives", "yields",  "because",  "when",  "as",  "at",
    "which", "while", "also", "so that",   "using", "we get",  "we have",  "i.e.,", "and so", "or equivalently"};

// unit symbols the reader recognises after a number (the checker decides what it knows)
constexpr std::array<std::string_view, 52> kUnits = {
    "kg", "g",   "mg",  "m",   "km",  "cm",  "mm",  "um",  "nm",  "s",   "ms",  "us",  "ns",
    "min", "h",  "A",   "mA",  "K",   "mol", "cd",  "N",   "kN",  "MN",  "J",   "kJ",  "MJ",
    "eV", "W",   "kW",  "MW",  "Pa",  "kPa", "MPa", "GPa", "Hz",  "kHz", "MHz", "rad", "sr",
    "V",  "C",   "F",   "T",   "Wb",  "H",   "L",   "bar", "atm", "deg", "rpm", "Ohm", "ohm"};

}  // namespace

bool is_greek(std::string_view cs) { return in_hashed(kGreek, cs); }

const char* function_name(std::string_view cs) {
  static const std::array<std::pair<std::string_view, const char*>, 20> kFunctions = {{
      {"sin", "sin"},     {"cos", "cos"},     {"tan", "tan"},   {"arcsin", "asin"}, {"arccos", "acos"},
      {"arctan", "atan"}, {"sinh", "sinh"},   {"cosh", "cosh"}, {"tanh", "tanh"},   {"ln", "ln"},
      {"log", "log"},     {"exp", "exp"},     {"cot", "cot"},   {"sec", "sec"},     {"csc", "csc"},
      {"arsinh", "asinh"}, {"arcosh", "acosh"}, {"artanh", "atanh"}, {"sgn", "sgn"}, {"lg", "log10"},
  }};
  for (const auto& [k, v] : kFunctions)
    if (k == cs) return v;
  return nullptr;
}

bool relation_of(const Token& t, TexRel& rel) {
  if (t.kind == TokKind::Char) {
    if (t.text == "=") return rel = TexRel::Eq, true;
    if (t.text == "<") return rel = TexRel::Lt, true;
    if (t.text == ">") return rel = TexRel::Gt, true;
    return false;
  }
  if (t.kind != TokKind::Cs) return false;
  static const std::unordered_map<std::string_view, TexRel> kRels = {
      {"approx", TexRel::Approx},     {"simeq", TexRel::Approx},     {"sim", TexRel::Approx},
      {"thickapprox", TexRel::Approx}, {"le", TexRel::Le},           {"leq", TexRel::Le},
      {"leqslant", TexRel::Le},       {"ge", TexRel::Ge},            {"geq", TexRel::Ge},
      {"geqslant", TexRel::Ge},       {"lt", TexRel::Lt},            {"gt", TexRel::Gt},
      {"ne", TexRel::Ne},             {"neq", TexRel::Ne},           {"equiv", TexRel::Eq},
      {"coloneqq", TexRel::Eq},       {"eqqcolon", TexRel::Eq},      {"doteq", TexRel::Eq},
      {"Rightarrow", TexRel::Gives},  {"implies", TexRel::Gives},    {"Longrightarrow", TexRel::Gives},
      {"rightarrow", TexRel::Gives},  {"longrightarrow", TexRel::Gives}, {"to", TexRel::Gives},
      {"therefore", TexRel::Gives},   {"iff", TexRel::Gives},        {"Leftrightarrow", TexRel::Gives},
      {"Longleftrightarrow", TexRel::Gives}, {"mapsto", TexRel::Gives}, {"leadsto", TexRel::Gives},
  };
  auto it = kRels.find(t.text);
  if (it != kRels.end()) return rel = it->second, true;
  return false;
}

bool is_ignored_cs(std::string_view cs) { return in_hashed(kIgnored, cs); }
bool is_size_cs(std::string_view cs) { return in_hashed(kSizes, cs); }

bool is_separator_word(std::string_view text) {
  std::size_t b = text.find_first_not_of(" ,;.:");
  if (b == std::string_view::npos) return true;  // only spaces or punctuation
  std::size_t e = text.find_last_not_of(" ,;.:");
  std::string_view w = text.substr(b, e - b + 1);
  if (in(kWords, w)) return true;
  // prose: more than one word, or one word followed by ':' ("x-direction:")
  return w.find(' ') != std::string_view::npos && !looks_like_unit(w);
}

std::string unit_text(std::string_view tex) {
  std::string out;
  auto sep = [&] {
    if (!out.empty() && out.back() != '*' && out.back() != '/') out += '*';
  };
  for (std::size_t i = 0; i < tex.size(); ++i) {
    char c = tex[i];
    if (c == '\\') {
      std::size_t j = i + 1;
      while (j < tex.size() && ((tex[j] >= 'a' && tex[j] <= 'z') || (tex[j] >= 'A' && tex[j] <= 'Z'))) ++j;
      std::string_view cs = tex.substr(i + 1, std::max<std::size_t>(j, i + 2) - i - 1);
      if (cs == "cdot" || cs == "," || cs == ";" || cs == ":" || cs == " " || cs == "times") {
        sep();
      } else if (cs == "Omega") {
        out += "ohm";
      } else if (cs == "mu") {
        out += "u";
      } else if (cs == "circ") {
        out += "deg";
      }
      i = std::max(j, i + 2) - 1;
      continue;
    }
    if (c == ' ' || c == '~' || c == '.') {
      // a space between units is a product; spaces before '/' or '^' or at the ends are not
      std::size_t k = tex.find_first_not_of(" ~.", i);
      if (k != std::string_view::npos && !out.empty() && tex[k] != '/' && tex[k] != '^' && tex[k] != '}')
        sep();
      i = (k == std::string_view::npos ? tex.size() : k) - 1;
      continue;
    }
    if (c == '{' || c == '}') continue;
    if (c == '^') {
      out += '^';
      continue;
    }
    out += c;
  }
  while (!out.empty() && (out.back() == '*' || out.back() == '/')) out.pop_back();
  return out;
}

bool looks_like_unit(std::string_view text) {
  std::string u = unit_text(text);
  if (u.empty()) return false;
  std::size_t i = 0;
  bool any = false;
  while (i < u.size()) {
    char c = u[i];
    if (c == '*' || c == '/' || c == '^' || c == '-' || c == '(' || c == ')' || (c >= '0' && c <= '9')) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < u.size() && ((u[j] >= 'a' && u[j] <= 'z') || (u[j] >= 'A' && u[j] <= 'Z'))) ++j;
    if (j == i) return false;
    if (!in(kUnits, std::string_view(u).substr(i, j - i))) return false;
    any = true;
    i = j;
  }
  return any;
}

}  // namespace dc::tex
