#include "derivations/document/document.hpp"
#include "derivations/exec/batch.hpp"

#include <sys/stat.h>

#include <chrono>
#include <cstring>
#include <deque>
#include <fstream>
#include <stdexcept>

#include "derivations/claims/claims.hpp"
#include "derivations/syntax/io.hpp"
#include "derivations/exec/pool.hpp"
#include "derivations/exec/progress.hpp"
#include "derivations/exec/read_once.hpp"
#include "derivations/exec/wire.hpp"

namespace dc::exec {
namespace {

std::string u32_bytes(std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); }
std::uint32_t read_u32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, s.data() + at, 4);
  return v;
}

// The reason of an outcome that did not finish, as verdicts and errors print it.
std::string budget_reason(const TaskOutcome& o) { return o.reason; }

// Reads every file in a worker first: a file whose reading runs away costs a worker, not the
// run. Returns, per file, the error if reading failed.
std::vector<std::optional<InputError>> try_reading(const std::vector<std::string>& files, const RunOptions& opt) {
  Pool pool(std::min<int>(opt.jobs, static_cast<int>(std::max<std::size_t>(1, files.size()))), opt.budget,
            [&files](const std::string& task) -> std::string {
              const std::string& path = files[read_u32(task, 0)];
              try {
                (void)load_any(path);
                return "";
              } catch (const InputError& e) {
                return encode(e);
              }
            });
  std::vector<std::optional<InputError>> out;
  std::size_t i = 0;
  pool.run(
      [&](std::string& task) {
        if (i >= files.size()) return false;
        task = u32_bytes(static_cast<std::uint32_t>(i++));
        return true;
      },
      [&](TaskOutcome&& o) {
        const std::string& path = files[out.size()];
        if (!o.done())
          out.emplace_back(InputError({path, 0, 0}, "reading this file did not finish: " + budget_reason(o) +
                                                        "; it was not checked"));
        else if (o.payload.empty())
          out.emplace_back(std::nullopt);
        else
          out.emplace_back(decode_input_error(o.payload));
      });
  return out;
}

}  // namespace

std::vector<FileReport> check_files(const std::vector<std::string>& files, const RunOptions& opt) {
  std::vector<FileReport> reports(files.size());
  struct StepRef {
    std::uint32_t file, step;
  };
  std::vector<StepRef> steps;
  if (opt.read_once) {
    std::vector<ReadFile> read = read_files_once(files, opt.budget);   // from here on, in the reading child
    for (std::size_t f = 0; f < files.size(); ++f) {
      reports[f].file = files[f];
      if (read[f].error) {
        reports[f].input_error = std::move(*read[f].error);
        continue;
      }
      reports[f].derivation = std::move(read[f].derivation);
      reports[f].seconds = read[f].seconds;
    }
  } else {
    std::vector<std::optional<InputError>> read_errors = try_reading(files, opt);
    for (std::size_t f = 0; f < files.size(); ++f) {
      reports[f].file = files[f];
      if (read_errors[f]) {
        reports[f].input_error = *read_errors[f];
        continue;
      }
      auto t0 = std::chrono::steady_clock::now();
      try {
        reports[f].derivation.emplace(load_any(files[f]));
      } catch (const InputError& e) {   // the worker read it; a second read should agree
        reports[f].input_error = e;
        continue;
      }
      reports[f].seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
  }
  for (std::size_t f = 0; f < files.size(); ++f) {
    if (!reports[f].derivation) continue;
    for (std::size_t s = 0; s < reports[f].derivation->steps.size(); ++s)
      steps.push_back({static_cast<std::uint32_t>(f), static_cast<std::uint32_t>(s)});
  }
  // The workers are forked now, so each holds every parsed derivation (copy on write).
  const ProveOptions prove = opt.prove;
  Pool pool(std::min<int>(opt.jobs, static_cast<int>(std::max<std::size_t>(1, steps.size()))), opt.budget,
            [&reports, prove](const std::string& task) -> std::string {
              const Derivation& d = *reports[read_u32(task, 0)].derivation;
              return encode(check_any_step(d, d.steps[read_u32(task, 4)], prove));
            });
  Progress progress(opt.progress, "steps");
  std::size_t next = 0, delivered = 0;
  pool.run(
      [&](std::string& task) {
        if (next >= steps.size()) return false;
        task = u32_bytes(steps[next].file) + u32_bytes(steps[next].step);
        ++next;
        return true;
      },
      [&](TaskOutcome&& o) {
        const StepRef ref = steps[delivered++];
        FileReport& fr = reports[ref.file];
        const Step* step = &fr.derivation->steps[ref.step];
        StepResult r;
        if (o.done()) {
          r = decode_step_result(o.payload, step);
        } else {
          r.step = step;
          r.verdict.kind = VerdictKind::Undecided;
          r.verdict.method = "budget";
          r.verdict.reason = budget_reason(o);
          r.seconds = o.seconds;
        }
        fr.seconds += r.seconds;
        fr.summary.add(std::move(r));
        progress.update(static_cast<long>(delivered), static_cast<double>(delivered) / static_cast<double>(steps.size()));
      });
  return reports;
}

Shard parse_shard(const std::string& text) {
  auto slash = text.find('/');
  Shard s;
  try {
    if (slash == std::string::npos) throw std::invalid_argument("");
    std::size_t a = 0, b = 0;
    s.index = std::stoi(text.substr(0, slash), &a);
    s.count = std::stoi(text.substr(slash + 1), &b);
    if (a != slash || b != text.size() - slash - 1) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw std::invalid_argument("--shard expects K/N (e.g. 2/8), got '" + text + "'");
  }
  if (s.count < 1 || s.index < 1 || s.index > s.count)
    throw std::invalid_argument("--shard K/N needs 1 <= K <= N, got '" + text + "'");
  return s;
}

void ClaimsTally::count(const std::string& verdict) {
  ++claims;
  if (verdict == "error") malformed = true;
  else if (verdict == "refuted") refuted = true;
  else if (verdict == "undecided") undecided = true;
}

int ClaimsTally::exit_code() const {
  if (malformed) return kExitInputError;
  if (refuted) return kExitRefuted;
  if (undecided) return kExitUndecided;
  return kExitOk;
}

namespace {

std::string verdict_of(const std::string& json_line) {
  nlohmann::json j = nlohmann::json::parse(json_line, nullptr, false);
  return j.is_object() && j.contains("verdict") && j.at("verdict").is_string() ? j.at("verdict").get<std::string>() : "";
}

}  // namespace

ClaimsTally check_claims(const std::string& file, const Shard& shard, bool timings, const RunOptions& opt,
                         std::ostream& out) {
  InputFile in(file, InputFile::Streams::Allowed);   // a bank may come from a pipe: `... | derivcheck claims -`
  LineReader reader(in);
  struct stat st {};
  double total_bytes =
      file != "-" && ::stat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 ? static_cast<double>(st.st_size) : -1;
  double read_bytes = 0;
  // A task: line number (4 bytes), too-long flag (1 byte), then the line (or its length).
  const ProveOptions prove = opt.prove;
  Pool pool(opt.jobs, opt.budget, [file, timings, prove](const std::string& task) -> std::string {
    int line_no = static_cast<int>(read_u32(task, 0));
    std::string text = task.substr(5);
    nlohmann::ordered_json r =
        task[4] ? claim_line_error(line_no, file,
                                   "the line is " + text + " bytes long; a claim may be at most " +
                                       std::to_string(kMaxInputLineBytes >> 20) + " MiB")
                : check_claim_line(text, line_no, file, prove);
    if (!timings) r.erase("seconds");
    return json_text(r);
  });
  struct Pending {
    int line_no;
    std::string text;
  };
  std::deque<Pending> pending;   // dispatched, not yet written: at most the pool's window
  ClaimsTally tally;
  Progress progress(opt.progress, "claims");
  LineReader::Line line;
  pool.run(
      [&](std::string& task) {
        while (reader.next(line)) {
          read_bytes += static_cast<double>(line.length) + 1;
          if (!shard.takes(line.number)) continue;
          if (!line.too_long && line.text.find_first_not_of(" \t") == std::string::npos) continue;
          task = u32_bytes(static_cast<std::uint32_t>(line.number)) + std::string(1, line.too_long ? '\1' : '\0') +
                 (line.too_long ? std::to_string(line.length) : line.text);
          pending.push_back({line.number, line.too_long ? std::string() : line.text});
          return true;
        }
        return false;
      },
      [&](TaskOutcome&& o) {
        Pending p = std::move(pending.front());
        pending.pop_front();
        std::string result;
        if (o.done()) {
          result = std::move(o.payload);
        } else {
          nlohmann::ordered_json r = claim_line_undecided(p.text, p.line_no, "budget", budget_reason(o));
          if (timings) r["seconds"] = o.seconds;
          result = json_text(r);
        }
        tally.count(verdict_of(result));
        out << result << '\n';
        progress.update(tally.claims, total_bytes > 0 ? read_bytes / total_bytes : -1);
      });
  out.flush();
  if (tally.claims == 0 && shard.count == 1)
    throw InputError({file, 0, 0}, "no claims (the file is empty or has only blank lines); expected one JSON object per line");
  return tally;
}

ClaimsTally merge_claim_results(const std::vector<std::string>& files, std::ostream& out) {
  struct Source {
    std::unique_ptr<InputFile> file;
    std::unique_ptr<LineReader> reader;
    LineReader::Line line;
    long key = 0;
    bool live = false;
  };
  std::vector<Source> sources(files.size());
  auto advance = [&](Source& s) {
    s.live = false;
    while (s.reader->next(s.line)) {
      if (s.line.text.find_first_not_of(" \t") == std::string::npos) continue;
      nlohmann::json j = nlohmann::json::parse(s.line.text, nullptr, false);
      if (s.line.too_long || !j.is_object() || !j.contains("line") || !j.at("line").is_number_integer())
        throw InputError({s.file->path(), s.line.number, 1},
                         "not a result line of `derivcheck claims` (a JSON object with an integer \"line\")");
      long key = j.at("line").get<long>();
      if (key <= s.key)
        throw InputError({s.file->path(), s.line.number, 1},
                         "result lines are not in increasing line order (line " + std::to_string(key) + " after " +
                             std::to_string(s.key) + ")");
      s.key = key;
      s.live = true;
      return;
    }
  };
  for (std::size_t i = 0; i < files.size(); ++i) {
    sources[i].file = std::make_unique<InputFile>(files[i]);
    sources[i].reader = std::make_unique<LineReader>(*sources[i].file);
    advance(sources[i]);
  }
  ClaimsTally tally;
  long last = 0;
  for (;;) {
    Source* best = nullptr;
    for (auto& s : sources)
      if (s.live && (!best || s.key < best->key)) best = &s;
    if (!best) break;
    if (best->key == last)
      throw InputError({best->file->path(), best->line.number, 1},
                       "line " + std::to_string(best->key) + " appears in more than one shard");
    last = best->key;
    tally.count(verdict_of(best->line.text));
    out << best->line.text << '\n';
    advance(*best);
  }
  out.flush();
  return tally;
}

}  // namespace dc::exec
