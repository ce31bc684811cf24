// Closed forms from the derivation files (see derived.hpp).
#include "numeric/scenes/derived.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>

#include "derivations/reader/derivation.hpp"
#include "derivations/syntax/source.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/reference/reference.hpp"

namespace dc::scenes {

namespace {

struct Cached {
  std::unique_ptr<Derivation> d;   // null if it could not be loaded
  std::string error;
};

const Cached& load_cached(const std::string& path) {
  static std::mutex mu;
  static std::map<std::string, Cached> cache;
  std::lock_guard<std::mutex> lock(mu);
  auto it = cache.find(path);
  if (it != cache.end()) return it->second;
  Cached c;
  try {
    if (!std::filesystem::exists(path)) {
      c.error = "no file " + path;
    } else {
      c.d = std::make_unique<Derivation>(load_derivation(path));
    }
  } catch (const InputError& e) {
    c.error = e.format();
  } catch (const std::exception& e) {
    c.error = e.what();
  }
  return cache.emplace(path, std::move(c)).first->second;
}

}  // namespace

std::optional<double> derived_value(const std::string& dir, const std::string& file, const std::string& label,
                                    const std::map<std::string, double>& at, std::string* why) {
  auto fail = [&](std::string reason) -> std::optional<double> {
    if (why) *why = std::move(reason);
    return std::nullopt;
  };
  if (dir.empty()) return fail("no derivation directory given");
  const Cached& c = load_cached((std::filesystem::path(dir) / file).string());
  if (!c.d) return fail(c.error);
  try {
    const Formula f = formula(*c.d, label);
    std::vector<std::pair<std::string, GiNaC::numeric>> values;
    for (const auto& sym : f.params) {
      const SymbolInfo* info = c.d->symbols.find(sym);
      const std::string name = info ? info->name : sym.get_name();
      const auto it = at.find(name);
      if (it == at.end()) return fail(file + ":" + label + " needs '" + name + "', which the scene does not set");
      values.emplace_back(name, num::exact_rational(it->second, "closed-form argument"));
    }
    num::bind_point(*c.d, f, values);  // checks the declared domains and assumptions
    // The point is keyed by the symbols as they occur in the expression: Formula::params holds
    // them as GiNaC::symbol, which slices a possymbol (positive symbols), and a sliced key does
    // not match the possymbol in the expression.
    GiNaC::exmap point;
    std::map<std::string, GiNaC::numeric> by_name(values.begin(), values.end());
    std::function<void(const GiNaC::ex&)> walk = [&](const GiNaC::ex& e) {
      if (GiNaC::is_a<GiNaC::symbol>(e)) {
        const SymbolInfo* info = c.d->symbols.find(GiNaC::ex_to<GiNaC::symbol>(e));
        const std::string name = info ? info->name : GiNaC::ex_to<GiNaC::symbol>(e).get_name();
        if (auto it = by_name.find(name); it != by_name.end()) point[e] = it->second;
        return;
      }
      for (std::size_t i = 0; i < e.nops(); ++i) walk(e.op(i));
    };
    walk(f.expr);
    return num::round_to_double(num::reference_value(f.expr, point, 20));
  } catch (const InputError& e) {
    return fail(e.message());
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}

Comparison closed_form(const RunOptions& opt, std::string quantity, std::string unit, double simulated,
                       double builtin, std::string formula, const std::string& file, const std::string& label,
                       const std::map<std::string, double>& at) {
  Comparison c{std::move(quantity), std::move(unit), simulated, builtin, std::move(formula), "built-in"};
  std::string why;
  if (auto v = derived_value(opt.derivations, file, label, at, &why)) {
    c.closed_form = *v;
    c.builtin = builtin;
    c.source = file + ":" + label;
  } else if (!opt.derivations.empty()) {
    c.source = "built-in (" + why + ")";
  }
  return c;
}

}  // namespace dc::scenes
