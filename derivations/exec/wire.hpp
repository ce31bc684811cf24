// Results crossing from a worker process to the parent: a step's StepResult (without its Step
// pointer, which the parent restores) and an InputError, as length-prefixed binary fields.
// Both ends are the same binary, so the format has no versioning.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "derivations/rules/check.hpp"
#include "derivations/syntax/source.hpp"

namespace dc::exec {

// Length-prefixed fields in native byte order (both ends are the same binary).
class Writer {
 public:
  void u64(std::uint64_t v);
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  void f64(double v);   // bit pattern: inf and NaN survive
  void str(const std::string& s);
  void pairs(const std::vector<std::pair<std::string, std::string>>& p);
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

class WireReader {
 public:
  explicit WireReader(const std::string& in) : in_(in) {}
  std::uint64_t u64();
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64();
  std::string str();
  std::vector<std::pair<std::string, std::string>> pairs();

 private:
  void need(std::uint64_t n) const;
  const std::string& in_;
  std::size_t at_ = 0;
};

std::string encode(const StepResult& r);
StepResult decode_step_result(const std::string& bytes, const Step* step);

std::string encode(const InputError& e);
InputError decode_input_error(const std::string& bytes);

}  // namespace dc::exec
