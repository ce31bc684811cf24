// Differentials d(x) as symbols of their own (differential.hpp).
#include "derivations/symbolic/differential.hpp"

#include "derivations/symbolic/functions.hpp"

namespace dc {

namespace {

constexpr const char* kWhatIsRead =
    "d(...) is the differential of a symbol, d(x), or of a function of one variable, d(f(t)); write the "
    "differential of an expression out by the chain rule, d(x^2) = 2*x*d(x)";

// The function of one variable that `a` applies to that variable (vr(t)), else nullptr.
const SymbolInfo* function_of_its_variable(const Node& a, const SymbolTable& table) {
  if (a.kind != NodeKind::Call || a.args.size() != 1) return nullptr;
  const SymbolInfo* f = table.find(a.text);
  if (!f || !f->is_function || f->params.size() != 1) return nullptr;
  const Node& t = a.args[0];
  return t.kind == NodeKind::Symbol && t.text == f->params[0] ? f : nullptr;
}

}  // namespace

bool is_differential_call(const Node& n, const SymbolTable& table) {
  if (n.kind != NodeKind::Call || n.text != "d" || n.args.size() != 1) return false;
  const SymbolInfo* f = table.find("d");
  return !(f && f->is_function);
}

bool has_differential_call(const Node& n, const SymbolTable& table) {
  if (is_differential_call(n, table)) return true;
  for (const auto& a : n.args)
    if (has_differential_call(a, table)) return true;
  return false;
}

std::string differential_name(const std::string& of) { return "d(" + of + ")"; }

void declare_differentials(const Node& n, SymbolTable& table) {
  for (const auto& a : n.args) declare_differentials(a, table);
  if (!is_differential_call(n, table)) return;
  const Node& a = n.args[0];
  const SymbolInfo* x = nullptr;
  if (a.kind == NodeKind::Symbol) {
    x = table.find(a.text);
    if (!x) return;   // the conversion reports the undefined symbol
    if (x->is_function || x->is_differential) throw InputError(a.pos, kWhatIsRead, a.length);
  } else if (const SymbolInfo* f = function_of_its_variable(a, table)) {
    x = table.find(f->params[0]);
    if (!x) return;
  } else {
    throw InputError(a.pos, kWhatIsRead, a.length);
  }
  if (table.find(differential_name(x->name))) return;
  SymbolInfo info;
  info.name = differential_name(x->name);
  info.tex = "\\mathrm{d}" + x->tex;
  info.dimension = x->dimension;
  info.has_dimension = x->has_dimension;
  info.unit = x->unit;
  info.pos = n.pos;
  info.is_differential = true;
  table.declare(std::move(info));
}

GiNaC::ex differential_value(const Node& n, const SymbolTable& table, const GiNaC::ex& converted_arg) {
  const Node& a = n.args[0];
  std::string of;
  const SymbolInfo* f = nullptr;
  if (a.kind == NodeKind::Symbol) of = a.text;
  else if ((f = function_of_its_variable(a, table))) of = f->params[0];
  else throw InputError(a.pos, kWhatIsRead, a.length);
  const SymbolInfo* d = table.find(differential_name(of));
  if (!d)
    throw InputError(n.pos, "the differential " + differential_name(of) + " is read only in a derivation's steps",
                     n.length);
  if (!f) return d->sym;
  const SymbolInfo* t = table.find(of);
  if (!t || !GiNaC::is_a<GiNaC::symbol>(t->sym)) throw InputError(a.pos, kWhatIsRead, a.length);
  return converted_arg.diff(GiNaC::ex_to<GiNaC::symbol>(t->sym)) * d->sym;
}

std::vector<DifferentialOf> differentials_in(const GiNaC::ex& e, const SymbolTable& table) {
  std::vector<DifferentialOf> out;
  for (const auto& info : table.all()) {
    if (!info.is_differential || !e.has(info.sym)) continue;
    const std::string of = info.name.substr(2, info.name.size() - 3);
    const SymbolInfo* x = table.find(of);
    if (x) out.push_back({info.sym, x->sym, x});
  }
  return out;
}

GiNaC::ex differential_of(const GiNaC::ex& x, const SymbolTable& table) {
  if (!GiNaC::is_a<GiNaC::symbol>(x)) return {};
  const SymbolInfo* info = table.find(GiNaC::ex_to<GiNaC::symbol>(x));
  if (!info || info->is_function || info->is_differential) return {};
  const SymbolInfo* d = table.find(differential_name(info->name));
  return d ? d->sym : GiNaC::ex();
}

}  // namespace dc
