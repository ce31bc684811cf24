// Hostile input for the CLI and the I/O layer (issue 12, items 4, 5 and 8): bytes that are not
// UTF-8, a BOM, CR and CRLF line endings, bad claim lines among good ones, inputs that are not
// regular files (directories, devices, FIFOs, /proc/self/mem, files over the size limit, empty
// files), output paths that are inputs, links, FIFOs or devices, signals while an output is
// being written, and the messages for self references, cyclic definitions and huge unit
// exponents. Every case must end with a clear error or verdict: exit 0-3, never 4, never a hang.
#include "cli/cli_run.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <nlohmann/json.hpp>

#include "derivations/syntax/io.hpp"
#include "derivations/syntax/source.hpp"

namespace fs = std::filesystem;
using cli_test::lines_of;
using cli_test::run;
using cli_test::Run;
using cli_test::src;

namespace {

// A fresh directory per test case, removed at the end.
struct TempDir {
  fs::path dir;
  TempDir() {
    static int counter = 0;
    dir = fs::temp_directory_path() / ("dc_hostile_" + std::to_string(::getpid()) + "_" + std::to_string(++counter));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::string file(const std::string& name, const std::string& bytes) const {
    fs::path p = dir / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  // Names in the directory (to catch leftover temporaries).
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
};

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
  return s;
}

const std::string kGood = "symbol x : real [1]\n"
                          "a: x = x\n"
                          "    by given\n"
                          "b: x = 2*x - x\n"
                          "    by rewrite a\n";

}  // namespace

// --- claims: one bad line never stops the batch ---------------------------------------------

TEST_CASE("claims: every kind of bad line gets its own error result and the others are checked",
          "[cli][claims][hostile]") {
  TempDir t;
  const std::string good = R"({"id":"ok","kind":"equal","lhs":"x+x","rhs":"2*x"})";
  std::string huge = R"({"id":"huge","kind":"equal","lhs":")" + std::string((std::size_t{1} << 20) + 10, 'x') + R"(","rhs":"x"})";
  std::vector<std::string> bank = {
      good,                                                                         // 1
      "{\"id\":\"latin1\",\"kind\":\"equal\",\"lhs\":\"x\",\"rhs\":\"x\",\"note\":\"caf\xE9\"}",   // 2 (ignored field)
      "{\"id\":\"trunc\",\"kind\":\"equal\",\"lhs\":\"x\xC3",                        // 3 invalid and malformed
      R"({"id":"m","kind":"equal","lhs":"x",)",                                     // 4 malformed JSON
      R"({"id":"t1","kind":3,"lhs":"x","rhs":"x"})",                                // 5 kind not a string
      R"({"id":"t2","kind":"equal","lhs":["x"],"rhs":"x"})",                        // 6 lhs not a string
      R"({"id":"k","kind":"integral","lhs":"x","rhs":"x"})",                        // 7 unknown kind
      R"([1,2,3])",                                                                 // 8 not an object
      huge,                                                                         // 9 over the line limit
      std::string(100000, '[') + std::string(100000, ']'),                          // 10 deep nesting
      std::string("{\"id\":\"nul\",\"kind\":\"equal\",\"lhs\":\"x\",\"rhs\":\"x\"}\0", 46),  // 11 a NUL byte
      R"({"id":"last","kind":"equal","lhs":"x","rhs":"x"})",                        // 12
  };
  std::string text;
  for (const auto& l : bank) text += l + "\n";
  std::string f = t.file("bank.jsonl", text);
  Run r = run({"claims", "--no-timings", f}, 60);
  CAPTURE(r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.err.empty());
  auto out = lines_of(r.out);
  REQUIRE(out.size() == bank.size());
  std::vector<nlohmann::json> res;
  for (const auto& l : out) res.push_back(nlohmann::json::parse(l));   // every line is valid JSON
  for (std::size_t i = 0; i < res.size(); ++i) {
    CAPTURE(i, out[i].substr(0, 300));
    bool good_line = i == 0 || i == 11;
    CHECK(res[i]["verdict"] == (good_line ? "proved" : "error"));
    if (!good_line) {
      CHECK(res[i]["line"] == i + 1);
      CHECK(res[i]["error"].get<std::string>().rfind(f + ":" + std::to_string(i + 1) + ": error: ", 0) == 0);
      CHECK(out[i].size() < 2000);   // a huge line is not echoed back
    }
  }
  CHECK(res[1]["id"] == "latin1");
  CHECK(res[1]["error"].get<std::string>().find("invalid UTF-8 at column 62 (byte 0xE9)") != std::string::npos);
  CHECK(res[2]["error"].get<std::string>().find("invalid UTF-8") != std::string::npos);
  CHECK(res[3]["error"].get<std::string>().find("malformed JSON") != std::string::npos);
  CHECK(res[4]["error"].get<std::string>().find("field 'kind' must be a string") != std::string::npos);
  CHECK(res[5]["error"].get<std::string>().find("field 'lhs' must be a string") != std::string::npos);
  CHECK(res[6]["error"].get<std::string>().find("unknown kind 'integral'") != std::string::npos);
  CHECK(res[7]["error"].get<std::string>().find("expected a JSON object per line") != std::string::npos);
  CHECK(res[8]["error"].get<std::string>().find("a claim may be at most 1 MiB") != std::string::npos);
  CHECK(res[11]["id"] == "last");
}

TEST_CASE("claims: LF, CRLF and CR line endings and a BOM read the same claims", "[cli][claims][hostile]") {
  TempDir t;
  std::string lf = "{\"id\":\"a\",\"kind\":\"equal\",\"lhs\":\"x\",\"rhs\":\"x\"}\n"
                   "\n"
                   "{\"id\":\"b\",\"kind\":\"equal\",\"lhs\":\"x\",\"rhs\":\"2*x\"}\n"
                   "{\"id\":\"c\",\"kind\":\"equal\",\"lhs\":\"x\",";   // malformed, no final newline
  Run base = run({"claims", "--no-timings", t.file("lf.jsonl", lf)});
  CHECK(base.exit_code == 2);
  auto expected = lines_of(base.out);
  REQUIRE(expected.size() == 3);
  CHECK(expected[2].find("\"line\":4") != std::string::npos);
  for (auto [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"crlf.jsonl", replace_all(lf, "\n", "\r\n")},
           {"cr.jsonl", replace_all(lf, "\n", "\r")},
           {"bom.jsonl", "\xEF\xBB\xBF" + lf}}) {
    CAPTURE(name);
    std::string f = t.file(name, text);
    Run r = run({"claims", "--no-timings", f});
    CHECK(r.exit_code == 2);
    CHECK(replace_all(r.out, f, "X") == replace_all(base.out, t.path("lf.jsonl"), "X"));
  }
}

// --- check: encodings and line endings ----------------------------------------------------------

TEST_CASE("check --json: a Latin-1 note and a BOM give valid JSON, never an internal error", "[cli][check][hostile]") {
  TempDir t;
  std::string latin1 = t.file("latin1.dc", "title \"Caf\xE9\"\n" + kGood + "    note \"r\xE9sum\xE9\"\n");
  Run r = run({"check", "--json", latin1});
  CAPTURE(r.out, r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
  nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["files"][0]["steps"][1]["notes"][0] == "r\xEF\xBF\xBDsum\xEF\xBF\xBD");   // U+FFFD for each bad byte
  CHECK(j["exit_code"] == 0);

  std::string bom = t.file("bom.dc", "\xEF\xBB\xBF" + kGood);
  Run b = run({"check", "--json", bom});
  CHECK(b.exit_code == 0);
  CHECK(nlohmann::json::parse(b.out)["summary"]["steps"] == 2);
  Run bt = run({"check", bom});
  CHECK(bt.out.find(bom + ":2:1: \u2022 a given") != std::string::npos);
  CHECK(bt.out.find(bom + ":4:1: \u2713 b rewrite") != std::string::npos);

  // an error message quoting a Latin-1 line is valid JSON too
  std::string bad = t.file("bad.dc", "\xE9t\xE9: x = 1\n    by given\n");
  Run e = run({"check", "--json", bad});
  CHECK(e.exit_code == 2);
  CHECK(nlohmann::json::parse(e.out)["files"][0].contains("input_error"));
}

TEST_CASE("check: CR (old Mac), CRLF and LF files check the same steps at the same lines", "[cli][check][hostile]") {
  TempDir t;
  std::string text = slurp(src("tests/data/cli/refuted.dc"));
  REQUIRE(text.find('\r') == std::string::npos);
  std::string lf = t.file("lf.dc", text);
  Run base = run({"check", lf});
  CHECK(base.exit_code == 1);
  CHECK(base.out.find(lf + ":9:1: \u2717 v1p_wrong solve") != std::string::npos);
  for (auto [name, bytes] : std::vector<std::pair<std::string, std::string>>{
           {"cr.dc", replace_all(text, "\n", "\r")}, {"crlf.dc", replace_all(text, "\n", "\r\n")}}) {
    CAPTURE(name);
    std::string f = t.file(name, bytes);
    Run r = run({"check", f});
    CHECK(r.exit_code == 1);
    CHECK(replace_all(r.out, f, "X") == replace_all(base.out, lf, "X"));
  }
  // an error in a CR file points at the right line, and the quoted line has no CR in it
  std::string bad = t.file("bad_cr.dc", "symbol x : real [1]\ra: x = y\r    by given\r");
  Run e = run({"check", bad});
  CHECK(e.exit_code == 2);
  CHECK(e.out.find(bad + ":2:8: error: undefined symbol 'y'") != std::string::npos);
  CHECK(e.out.find("    a: x = y\n") != std::string::npos);
}

TEST_CASE("check: files without steps are input errors", "[cli][check][hostile]") {
  TempDir t;
  struct Case {
    const char* name;
    const char* text;
    const char* why;
  };
  auto c = GENERATE(values<Case>({{"empty.dc", "", "the file is empty"},
                                  {"blank.dc", "\n  \n\t\n", "only comments and blank lines"},
                                  {"comments.dc", "# a comment\n\n# another\n", "only comments"},
                                  {"decls.dc", "title \"t\"\nsymbol x : real [1]\n", "no step"}}));
  std::string f = t.file(c.name, c.text);
  Run r = run({"check", f});
  CAPTURE(r.out);
  CHECK(r.exit_code == 2);
  CHECK(r.out.find(f + ": error: no steps (") != std::string::npos);
  CHECK(r.out.find(c.why) != std::string::npos);
  // the other files of the run are still checked
  Run both = run({"check", f, src("tests/data/cli/all_hold.dc")});
  CHECK(both.exit_code == 2);
  CHECK(both.out.find("all_hold.dc:") != std::string::npos);
  CHECK(run({"latex", f}).exit_code == 2);
}

// --- inputs that are not regular files ------------------------------------------------------------

TEST_CASE("inputs that are not regular files are clear errors, never a hang or 0 steps", "[cli][hostile]") {
  TempDir t;
  std::string fifo = t.path("pipe.dc");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string dir = t.path("adir");
  fs::create_directories(dir);

  SECTION("check") {
    struct Case {
      std::string path, message;
    };
    for (const auto& c : std::vector<Case>{{"/proc/self/mem", "cannot read '/proc/self/mem': Input/output error"},
                                           {"/dev/zero", "it is a character device; only regular files are read"},
                                           {fifo, "it is a FIFO (named pipe); only regular files are read"},
                                           {t.path("missing.dc"), "No such file or directory"}}) {
      CAPTURE(c.path);
      Run r = run({"check", c.path}, 20);
      CHECK(r.exit_code == 2);
      CHECK(r.out.find(c.path + ": error: cannot read '" + c.path + "': ") != std::string::npos);
      CHECK(r.out.find(c.message) != std::string::npos);
      CHECK(r.out.find("1 file with input errors") != std::string::npos);
    }
    // a FIFO named *.dc inside a directory is reported, not skipped or waited for
    Run d = run({"check", t.dir.string()}, 20);
    CHECK(d.exit_code == 2);
    CHECK(d.out.find("pipe.dc: error: cannot read") != std::string::npos);
  }
  SECTION("claims") {
    for (const auto& p : std::vector<std::string>{dir, "/dev/zero", "/proc/self/mem"}) {
      CAPTURE(p);
      Run r = run({"claims", p}, 20);
      CHECK(r.exit_code == 2);
      CHECK(r.out.empty());
      CHECK(r.err.rfind(p + ": error: cannot read '" + p + "': ", 0) == 0);
    }
    CHECK(run({"claims", dir}).err.find("it is a directory; expected a file") != std::string::npos);
    Run e = run({"claims", t.file("empty.jsonl", "\n\n")});
    CHECK(e.exit_code == 2);
    CHECK(e.err.find("no claims") != std::string::npos);
  }
  SECTION("a claim bank is read from the standard input ('-') or a named pipe") {
    const std::string bank = t.file("bank.jsonl",
                                    "{\"kind\":\"equal\",\"lhs\":\"(x+1)^2\",\"rhs\":\"x^2+2*x+1\"}\n"
                                    "{\"kind\":\"equal\",\"lhs\":\"x\",\"rhs\":\"x+1\"}\n");
    auto check_results = [](const Run& r) {
      CHECK(r.exit_code == 1);   // the second claim is refuted
      const auto lines = cli_test::lines_of(r.out);
      REQUIRE(lines.size() == 2);
      CHECK(lines[0].find("\"line\":1,") != std::string::npos);
      CHECK(lines[0].find("\"verdict\":\"proved\"") != std::string::npos);
      CHECK(lines[1].find("\"verdict\":\"refuted\"") != std::string::npos);
    };
    check_results(run({"claims", "-", "--no-timings"}, 20, "cat " + bank + " | "));
    check_results(run({"claims", fifo, "--no-timings"}, 20, "cat " + bank + " > " + fifo + " & "));
    // an empty stream has no claims: an input error, as for an empty file
    Run e = run({"claims", "-"}, 20, "true | ");
    CHECK(e.exit_code == 2);
    CHECK(e.err.find("no claims") != std::string::npos);
  }
  SECTION("eval, latex, crosscheck and map") {
    for (const auto& cmd : std::vector<std::vector<std::string>>{{"eval", fifo, "a", "--at", "x=1"},
                                                                  {"latex", "/dev/zero"},
                                                                  {"crosscheck", fifo},
                                                                  {"map", "/proc/self/mem"}}) {
      CAPTURE(cmd);
      Run r = run(cmd, 20);
      CHECK(r.exit_code == 2);
      CHECK(r.err.find("error: cannot read") != std::string::npos);
    }
  }
  SECTION("a file over the size limit") {
    std::string big = t.path("big.dc");
    {
      int fd = ::open(big.c_str(), O_CREAT | O_WRONLY, 0600);
      REQUIRE(fd >= 0);
      REQUIRE(::ftruncate(fd, static_cast<off_t>(dc::kMaxInputFileBytes) + 1) == 0);   // sparse: costs no disk
      ::close(fd);
    }
    Run r = run({"check", big}, 60);
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("larger than the 64 MiB limit for an input file") != std::string::npos);
  }
  SECTION("an unreadable file") {
    std::string f = t.file("secret.dc", kGood);
    ::chmod(f.c_str(), 0);
    if (::geteuid() == 0) {
      SUCCEED("running as root: permissions do not apply");
    } else {
      Run r = run({"check", f});
      CHECK(r.exit_code == 2);
      CHECK(r.out.find("Permission denied") != std::string::npos);
    }
  }
}

TEST_CASE("the input reader: regular files only, bounded, CR/LF/CRLF lines", "[io][hostile]") {
  TempDir t;
  auto message = [](const std::function<void()>& f) -> std::string {
    try {
      f();
    } catch (const dc::InputError& e) {
      return e.format();
    }
    return "";
  };
  CHECK(message([&] { dc::read_file(t.dir.string()); }).find("it is a directory") != std::string::npos);
  CHECK(message([&] { dc::read_file("/dev/null"); }).find("character device") != std::string::npos);
  std::string f = t.file("ten.txt", "0123456789");
  CHECK(dc::read_file(f, 10) == "0123456789");
  CHECK(message([&] { dc::read_file(f, 9); }).find("larger than the 9 bytes limit") != std::string::npos);
  CHECK(dc::normalize_text("\xEF\xBB\xBF" "a\r\nb\rc\n") == "a\nb\nc\n");

  std::string lines = t.file("lines.txt", "\xEF\xBB\xBF" "one\r\ntwo\rthree\n\n" + std::string(50, 'x') + "\nlast");
  dc::InputFile in(lines);
  dc::LineReader reader(in, 20);
  dc::LineReader::Line l;
  std::vector<std::string> got;
  while (reader.next(l)) got.push_back(std::to_string(l.number) + ":" + (l.too_long ? "long:" : "") + l.text);
  CHECK(got == std::vector<std::string>{"1:one", "2:two", "3:three", "4:", "5:long:" + std::string(20, 'x'), "6:last"});
}

// --- output files -------------------------------------------------------------------------------------

TEST_CASE("latex -o and map -o: never over an input, through a link, never onto a FIFO or device", "[cli][output][hostile]") {
  TempDir t;
  std::string in = t.file("a.dc", kGood);
  const std::string before = slurp(in);

  SECTION("-o naming an input (also through a link or another spelling) is refused and the input kept") {
    std::string link = t.path("link.dc");
    fs::create_symlink(in, link);
    std::string other_spelling = (t.dir / "." / "a.dc").string();
    for (const auto& out : {in, link, other_spelling}) {
      CAPTURE(out);
      Run r = run({"latex", in, "-o", out});
      CHECK(r.exit_code == 2);
      CHECK(r.err.find("refusing to write '" + out + "': it is the input '" + in + "'") != std::string::npos);
      CHECK(slurp(in) == before);
      Run m = run({"map", t.dir.string(), "-o", out});
      CHECK(m.exit_code == 2);
      CHECK(slurp(in) == before);
    }
    CHECK(fs::is_symlink(link));
  }
  SECTION("a symbolic link at -o is written through: its target replaced, the link kept") {
    std::string target = t.file("real.tex", "old");
    std::string link = t.path("link.tex");
    fs::create_symlink("real.tex", link);   // relative, as people make them
    Run r = run({"latex", in, "-o", link});
    CHECK(r.exit_code == 0);
    CHECK(fs::is_symlink(link));
    CHECK(slurp(target).rfind("% Generated by derivcheck latex", 0) == 0);
    // a dangling link: its target is created
    std::string dangling = t.path("dangling.tex");
    fs::create_symlink("new.tex", dangling);
    CHECK(run({"latex", in, "-o", dangling}).exit_code == 0);
    CHECK(fs::is_symlink(dangling));
    CHECK(fs::is_regular_file(t.path("new.tex")));
  }
  SECTION("a FIFO, a device or a directory at -o is refused (and nothing blocks)") {
    std::string fifo = t.path("out.fifo");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    for (const auto& [out, why] : std::vector<std::pair<std::string, std::string>>{
             {fifo, "it is a FIFO (named pipe); only regular files are replaced"},
             {"/dev/null", "it is a character device; only regular files are replaced"},
             {t.dir.string(), "it is a directory"}}) {
      CAPTURE(out);
      Run r = run({"latex", in, "-o", out}, 20);
      CHECK(r.exit_code == 2);
      CHECK(r.err.find("cannot write '" + out + "': " + why) != std::string::npos);
    }
    CHECK(fs::is_fifo(fifo));
  }
  SECTION("no temporary is left behind; a replaced file keeps its mode") {
    std::string out = t.file("out.tex", "old");
    ::chmod(out.c_str(), 0640);
    CHECK(run({"latex", in, "-o", out}).exit_code == 0);
    struct stat st {};
    REQUIRE(::stat(out.c_str(), &st) == 0);
    CHECK((st.st_mode & 0777) == 0640);
    CHECK(run({"latex", in, "-o", t.path("missing/x.tex")}).exit_code == 2);
    CHECK(run({"latex", in, t.path("nope.dc"), "-o", out}).exit_code == 2);
    CHECK(t.names() == std::vector<std::string>{"a.dc", "out.tex"});
  }
}

TEST_CASE("write_file_atomic: a signal or a failure while writing removes the temporary", "[io][output][hostile]") {
  TempDir t;
  std::string out = t.file("out.txt", "previous");
  auto killed_while_writing = [&](int sig) {
    int ready[2];
    REQUIRE(::pipe(ready) == 0);
    pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      ::close(ready[0]);
      ::signal(SIGTERM, SIG_DFL);   // not Catch2's handlers: die as a plain program would
      ::signal(SIGINT, SIG_DFL);
      try {
        dc::write_file_atomic(out, [&](const dc::ByteSink& write) {
          write("half of the new content");
          (void)!::write(ready[1], "r", 1);
          for (;;) ::pause();   // the signal arrives here
        });
      } catch (...) {
      }
      ::_exit(0);
    }
    ::close(ready[1]);
    char c;
    REQUIRE(::read(ready[0], &c, 1) == 1);
    ::close(ready[0]);
    CHECK(t.names().size() == 2);   // out.txt and the temporary
    ::kill(child, sig);
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    CHECK(t.names() == std::vector<std::string>{"out.txt"});
    CHECK(slurp(out) == "previous");
  };
  SECTION("SIGTERM") { killed_while_writing(SIGTERM); }
  SECTION("SIGINT") { killed_while_writing(SIGINT); }
  SECTION("an exception from the producer") {
    CHECK_THROWS_AS(dc::write_file_atomic(out, [](const dc::ByteSink& write) {
                      write("partial");
                      throw std::runtime_error("boom");
                    }),
                    std::runtime_error);
    CHECK(t.names() == std::vector<std::string>{"out.txt"});
    CHECK(slurp(out) == "previous");
  }
  SECTION("success: the whole content, and the program's own handlers are back afterwards") {
    struct sigaction before {}, after {};
    ::sigaction(SIGTERM, nullptr, &before);
    dc::write_file_atomic(out, "new");
    CHECK(slurp(out) == "new");
    ::sigaction(SIGTERM, nullptr, &after);
    CHECK(after.sa_handler == before.sa_handler);
  }
}

// --- messages that mislead -------------------------------------------------------------------------------

TEST_CASE("messages: self reference, cyclic definitions, huge unit exponents", "[cli][check][hostile]") {
  TempDir t;
  SECTION("a step that uses itself says so") {
    std::string f = t.file("self.dc", "symbol x : real [1]\na: x = x\n    by rewrite a\n");
    Run r = run({"check", f});
    CHECK(r.exit_code == 2);
    CHECK(r.out.find(f + ":3:16: error: step 'a' refers to itself; a step may only use earlier steps") != std::string::npos);
    CHECK(r.out.find("defined later") == std::string::npos);
  }
  SECTION("cyclic definitions are an input error naming the cycle") {
    std::string f = t.file("cycle.dc",
                           "symbol u, v, w : real [1]\n"
                           "p: u = v + 1\n    by definition\n"
                           "q: v = 2*w\n    by definition\n"
                           "r: w = u - 1\n    by definition\n"
                           "s: u = 2*w + 1\n    by rewrite p\n");
    Run r = run({"check", f});
    CAPTURE(r.out);
    CHECK(r.exit_code == 2);
    CHECK(r.out.find(f + ":6:8: error: circular definition: w -> u -> v -> w ('u' is defined by step 'p' at 2:1, 'v' by "
                         "step 'q' at 4:1); a definition may not depend on itself") != std::string::npos);
    CHECK(r.out.find("nested too deeply") == std::string::npos);
  }
  SECTION("a huge unit exponent names the limit") {
    std::string f = t.file("unit.dc", "symbol m : positive [kg^100000]\na: m = m\n    by given\n");
    Run r = run({"check", f});
    CHECK(r.exit_code == 2);
    CHECK(r.out.find(f + ":1:25: error: unit exponent '100000' is too large: a unit exponent is an integer from -999 to 999") !=
          std::string::npos);
    std::string g = t.file("unit2.dc", "symbol m : positive [kg^2.5]\na: m = m\n    by given\n");
    CHECK(run({"check", g}).out.find("a unit exponent must be an integer") != std::string::npos);
    std::string h = t.file("unit3.dc", "symbol m : positive [kg^(-2.0)]\na: m = m\n    by given\n");
    CHECK(run({"check", h}).out.find("a unit exponent must be an integer") != std::string::npos);
  }
}
