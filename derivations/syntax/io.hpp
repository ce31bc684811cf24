// Input and output files, the one place where derivcheck touches the file system for data.
//
// Inputs: every command reads its files through InputFile (read_file, LineReader), which
// opens without blocking, checks with fstat that the path is a regular file and reads at most
// a fixed number of bytes, so a directory, a device, a FIFO, /proc/self/mem or a read error
// is a clear InputError ("cannot read 'x': ...", exit 2), never a hang or "0 steps".
//
// Outputs: write_file_atomic writes a temporary file created with mkstemp beside the target,
// then renames it over the target; the temporary is removed on failure and on
// SIGINT/SIGTERM/SIGHUP. The limits and rules are described in docs/cli.md ("Files").
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace dc {

// Limits on inputs (docs/cli.md).
constexpr std::size_t kMaxInputFileBytes = std::size_t{64} << 20;   // a whole file read at once
constexpr std::size_t kMaxInputLineBytes = std::size_t{1} << 20;    // one line of a claim bank

// A readable regular file. The constructor opens `path` with O_NONBLOCK (a FIFO never blocks)
// and refuses anything fstat does not call a regular file; every failure is an InputError at
// the file ("path: error: cannot read 'path': reason").
class InputFile {
 public:
  // Only regular files are opened, unless streams are allowed: then "-" is the standard input
  // and a named pipe (`/dev/stdin` on a pipe) is read too. A stream is read once, front to back.
  enum class Streams { Refused, Allowed };
  explicit InputFile(const std::string& path, Streams streams = Streams::Refused);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& path() const { return path_; }
  // Up to n bytes; 0 at the end of the file. A read error is an InputError.
  std::size_t read(char* buf, std::size_t n);

 private:
  std::string path_;
  int fd_ = -1;
};

// The whole content of a regular file of at most max_bytes bytes (a larger one is an
// InputError naming the limit). The bytes are returned as they are; see normalize_text.
std::string read_file(const std::string& path, std::size_t max_bytes = kMaxInputFileBytes);

// Text as the readers see it: a leading UTF-8 byte order mark removed, CRLF and a lone CR
// (old Mac OS) turned into LF, so line numbers count lines the way editors do.
std::string normalize_text(std::string text);

// The lines of an input file, one at a time in bounded memory. LF, CRLF and CR all end a
// line; a UTF-8 BOM at the start of the file is skipped. A line longer than max_line bytes is
// returned with too_long set, its text cut at max_line bytes (the rest is skipped).
class LineReader {
 public:
  struct Line {
    std::string text;           // without the line ending
    int number = 0;             // 1-based
    bool too_long = false;
    std::size_t length = 0;     // the full length in bytes, also when too_long
  };
  explicit LineReader(InputFile& in, std::size_t max_line = kMaxInputLineBytes);
  // The next line; false at the end of the file.
  bool next(Line& line);

 private:
  bool fill();
  InputFile& in_;
  std::size_t max_line_;
  std::string buf_;
  std::size_t at_ = 0;
  bool eof_ = false, started_ = false, after_cr_ = false;
  int number_ = 0;
};

// The byte offset of the first byte that is not part of valid UTF-8 (overlong forms,
// surrogates and code points above U+10FFFF are invalid), or npos when `s` is valid.
std::size_t invalid_utf8_at(std::string_view s);

// JSON text that never throws: bytes that are not valid UTF-8 are replaced by U+FFFD.
std::string json_text(const nlohmann::json& j, int indent = -1);
std::string json_text(const nlohmann::ordered_json& j, int indent = -1);

// Writes `content` to `path` atomically: a temporary file created with mkstemp (O_EXCL) in the
// target's directory, written, flushed to disk and renamed over the target; the target is
// either the old file or the whole new one. The temporary is removed when anything fails and
// when SIGINT, SIGTERM or SIGHUP arrives while it exists. A symbolic link at `path` is written
// through (the file it points to is replaced, the link is kept); a directory, FIFO, device or
// socket at `path` (or behind the link) is refused. A new file gets mode 0666 minus the umask,
// a replaced one keeps its mode. Failures throw InputError at the output file ("cannot write
// 'path': reason"); the target is then untouched.
void write_file_atomic(const std::string& path, const std::string& content);
// The same, with the content produced piece by piece: `produce` calls the sink as often as it
// likes; nothing is renamed into place until it returns (an exception from it removes the
// temporary and propagates).
using ByteSink = std::function<void(std::string_view)>;
void write_file_atomic(const std::string& path, const std::function<void(const ByteSink&)>& produce);
// The same, for content another program writes by name (gnuplot's `set output`): `produce`
// gets the temporary file's path and must fill that file in place (open and truncate it,
// not replace it).
void write_file_atomic_at(const std::string& path, const std::function<void(const std::string& temp_path)>& produce);

// An InputError when `output` is one of the `inputs` (the same file: device and inode, so
// links and other spellings count), checked before any work is done.
void refuse_output_over_inputs(const std::string& output, const std::vector<std::string>& inputs,
                               const std::string& option = "-o");

// The derivation files named on a command line: a directory stands for its *.dc files in sorted order
// (an empty one, or one that cannot be listed, is an InputError), anything else is taken as a
// file (a missing or unreadable file then becomes an input error when it is read).
std::vector<std::string> derivation_files(const std::vector<std::string>& inputs);

}  // namespace dc
