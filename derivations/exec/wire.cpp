#include "derivations/exec/wire.hpp"

#include <cstring>
#include <stdexcept>

namespace dc::exec {

void Writer::u64(std::uint64_t v) { out_.append(reinterpret_cast<const char*>(&v), 8); }
void Writer::f64(double v) {
  std::uint64_t u;
  std::memcpy(&u, &v, 8);
  u64(u);
}
void Writer::str(const std::string& s) {
  u64(s.size());
  out_ += s;
}
void Writer::pairs(const std::vector<std::pair<std::string, std::string>>& p) {
  u64(p.size());
  for (const auto& [a, b] : p) {
    str(a);
    str(b);
  }
}

std::uint64_t WireReader::u64() {
  need(8);
  std::uint64_t v;
  std::memcpy(&v, in_.data() + at_, 8);
  at_ += 8;
  return v;
}
double WireReader::f64() {
  std::uint64_t u = u64();
  double v;
  std::memcpy(&v, &u, 8);
  return v;
}
std::string WireReader::str() {
  std::uint64_t n = u64();
  need(n);
  std::string s = in_.substr(at_, n);
  at_ += n;
  return s;
}
std::vector<std::pair<std::string, std::string>> WireReader::pairs() {
  std::vector<std::pair<std::string, std::string>> p(u64());
  for (auto& [a, b] : p) {
    a = str();
    b = str();
  }
  return p;
}
void WireReader::need(std::uint64_t n) const {
  if (n > in_.size() - at_) throw std::runtime_error("truncated result from a worker process");
}

namespace {

void put(Writer& w, const InputError& e) {
  w.str(e.pos().file);
  w.i64(e.pos().line);
  w.i64(e.pos().col);
  w.str(e.message());
  w.i64(e.length());
  w.str(e.line_text());
}

InputError get_error(WireReader& r) {
  SourcePos p;
  p.file = r.str();
  p.line = static_cast<int>(r.i64());
  p.col = static_cast<int>(r.i64());
  std::string message = r.str();
  int length = static_cast<int>(r.i64());
  std::string line = r.str();
  return InputError(p, message, length, line);
}

void put(Writer& w, const Verdict& v) {
  w.i64(static_cast<int>(v.kind));
  w.str(v.method);
  w.str(v.detail);
  w.i64(v.points);
  w.i64(v.digits);
  w.f64(v.max_rel_diff);
  w.str(v.false_accept);
  w.pairs(v.point);
  w.str(v.lhs_value);
  w.str(v.rhs_value);
  w.str(v.lhs_label);
  w.str(v.rhs_label);
  w.str(v.function_values);
  w.str(v.residual);
  w.str(v.reason);
  w.u64(v.side_conditions.size());
  for (const auto& c : v.side_conditions) {
    w.str(c.what);
    w.str(c.reason);
    w.i64(static_cast<int>(c.status));
    w.str(c.evidence);
    w.pairs(c.point);
  }
  w.str(v.hint);
}

Verdict get_verdict(WireReader& r) {
  Verdict v;
  v.kind = static_cast<VerdictKind>(r.i64());
  v.method = r.str();
  v.detail = r.str();
  v.points = static_cast<int>(r.i64());
  v.digits = static_cast<int>(r.i64());
  v.max_rel_diff = r.f64();
  v.false_accept = r.str();
  v.point = r.pairs();
  v.lhs_value = r.str();
  v.rhs_value = r.str();
  v.lhs_label = r.str();
  v.rhs_label = r.str();
  v.function_values = r.str();
  v.residual = r.str();
  v.reason = r.str();
  v.side_conditions.resize(r.u64());
  for (auto& c : v.side_conditions) {
    c.what = r.str();
    c.reason = r.str();
    c.status = static_cast<SideCondition::Status>(r.i64());
    c.evidence = r.str();
    c.point = r.pairs();
  }
  v.hint = r.str();
  return v;
}

}  // namespace

std::string encode(const StepResult& res) {
  Writer w;
  put(w, res.verdict);
  w.str(res.derived);
  w.str(res.dimension);
  w.u64(res.errors.size());
  for (const auto& e : res.errors) put(w, e);
  w.u64((res.erratum_reported ? 1u : 0u) | (res.premise ? 2u : 0u) | (res.input_error ? 4u : 0u));
  w.f64(res.seconds);
  w.str(res.found_rule);
  w.u64(res.found_rows.size());
  for (const auto& row : res.found_rows) w.str(row);
  w.str(res.found_line);
  w.str(res.found_claim);
  return w.take();
}

StepResult decode_step_result(const std::string& bytes, const Step* step) {
  WireReader r(bytes);
  StepResult res;
  res.step = step;
  res.verdict = get_verdict(r);
  res.derived = r.str();
  res.dimension = r.str();
  std::uint64_t n = r.u64();
  for (std::uint64_t i = 0; i < n; ++i) res.errors.push_back(get_error(r));
  std::uint64_t flags = r.u64();
  res.erratum_reported = flags & 1u;
  res.premise = flags & 2u;
  res.input_error = flags & 4u;
  res.seconds = r.f64();
  res.found_rule = r.str();
  const std::uint64_t rows = r.u64();
  for (std::uint64_t i = 0; i < rows; ++i) res.found_rows.push_back(r.str());
  res.found_line = r.str();
  res.found_claim = r.str();
  return res;
}

std::string encode(const InputError& e) {
  Writer w;
  put(w, e);
  return w.take();
}

InputError decode_input_error(const std::string& bytes) {
  WireReader r(bytes);
  return get_error(r);
}

}  // namespace dc::exec
