#include "derivations/syntax/io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

#include "derivations/syntax/source.hpp"

namespace dc {

namespace {

std::string errno_text(int err) { return std::strerror(err); }

std::string mib(std::size_t bytes) {
  if (bytes % (std::size_t{1} << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// What a file that is not a regular file is, for messages.
std::string file_kind(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISSOCK(m)) return "a socket";
  if (S_ISLNK(m)) return "a symbolic link";
  return "not a regular file";
}

// The file an error is about ("path: error: ..."); an empty name would print as ": error:".
std::string shown_name(const std::string& path) { return path.empty() ? "<empty file name>" : path; }

[[noreturn]] void cannot_read(const std::string& path, const std::string& why) {
  throw InputError({shown_name(path), 0, 0}, "cannot read '" + path + "': " + why);
}

[[noreturn]] void cannot_write(const std::string& path, const std::string& why) {
  throw InputError({shown_name(path), 0, 0}, "cannot write '" + path + "': " + why);
}

}  // namespace

// --- inputs ------------------------------------------------------------------------------------

InputFile::InputFile(const std::string& path, Streams streams) : path_(path) {
  if (path.empty()) cannot_read(path, "empty file name");
  const bool stream_ok = streams == Streams::Allowed;
  if (stream_ok && path == "-") {
    struct stat st {};
    if (::fstat(STDIN_FILENO, &st) == 0 && S_ISDIR(st.st_mode)) cannot_read(path, "the standard input is a directory");
    fd_ = ::fcntl(STDIN_FILENO, F_DUPFD_CLOEXEC, 3);
    if (fd_ < 0) cannot_read(path, "the standard input: " + errno_text(errno));
    return;
  }
  // Look before opening, so a device is never opened (opening some has side effects); fstat
  // below is the authority (the path may change in between).
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) cannot_read(path, errno_text(errno));
  if (stream_ok && S_ISFIFO(st.st_mode)) {
    do {
      fd_ = ::open(path.c_str(), O_RDONLY | O_NOCTTY | O_CLOEXEC);
    } while (fd_ < 0 && errno == EINTR);
    if (fd_ < 0) cannot_read(path, errno_text(errno));
    return;
  }
  if (!S_ISREG(st.st_mode)) {
    if (S_ISDIR(st.st_mode)) cannot_read(path, "it is a directory; expected a file");
    cannot_read(path, "it is " + file_kind(st.st_mode) + "; only regular files are read");
  }
  do {
    fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  } while (fd_ < 0 && errno == EINTR);
  if (fd_ < 0) cannot_read(path, errno_text(errno));
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    int err = errno;
    ::close(fd_);
    fd_ = -1;
    cannot_read(path, S_ISREG(st.st_mode) ? errno_text(err) : "it is " + file_kind(st.st_mode) + "; only regular files are read");
  }
  // A regular file never blocks; reads are plain blocking reads from here on.
  int flags = ::fcntl(fd_, F_GETFL);
  if (flags >= 0) ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t InputFile::read(char* buf, std::size_t n) {
  for (;;) {
    ssize_t got = ::read(fd_, buf, n);
    if (got >= 0) return static_cast<std::size_t>(got);
    if (errno == EINTR) continue;
    cannot_read(path_, errno_text(errno));
  }
}

std::string read_file(const std::string& path, std::size_t max_bytes) {
  InputFile in(path);
  std::string out;
  // st_size is only a hint (/proc files say 0): read until the end, one byte past the limit.
  // Chunks start small: resize() zero-fills, and a 64 KiB chunk for a 5 KB file cost more than
  // the parse in a freshly forked process (page faults).
  std::size_t chunk = 1 << 13;
  for (;;) {
    std::size_t old = out.size();
    std::size_t want = std::min(chunk, max_bytes + 1 - old);
    out.resize(old + want);
    std::size_t got = in.read(out.data() + old, want);
    out.resize(old + got);
    if (got == 0) break;
    if (out.size() > max_bytes)
      cannot_read(path, "it is larger than the " + mib(max_bytes) + " limit for an input file");
    if (chunk < (std::size_t{1} << 22)) chunk *= 2;
  }
  return out;
}

std::string normalize_text(std::string text) {
  std::size_t from = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  if (from == 0 && text.find('\r') == std::string::npos) return text;
  std::string out;
  out.reserve(text.size() - from);
  for (std::size_t i = from; i < text.size(); ++i) {
    char c = text[i];
    if (c == '\r') {
      out += '\n';
      if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
    } else {
      out += c;
    }
  }
  return out;
}

LineReader::LineReader(InputFile& in, std::size_t max_line) : in_(in), max_line_(std::max<std::size_t>(1, max_line)) {}

bool LineReader::fill() {
  if (eof_) return false;
  if (at_ > 0) {
    buf_.erase(0, at_);
    at_ = 0;
  }
  std::size_t old = buf_.size();
  buf_.resize(old + (1 << 16));
  std::size_t got = in_.read(buf_.data() + old, 1 << 16);
  buf_.resize(old + got);
  if (got == 0) eof_ = true;
  return got > 0;
}

bool LineReader::next(Line& line) {
  if (!started_) {
    started_ = true;
    while (buf_.size() - at_ < 3 && fill()) {
    }
    if (buf_.compare(at_, 3, "\xEF\xBB\xBF") == 0) at_ += 3;
  }
  if (after_cr_) {  // the LF of a CRLF
    if (at_ == buf_.size()) fill();
    if (at_ < buf_.size() && buf_[at_] == '\n') ++at_;
    after_cr_ = false;
  }
  line.text.clear();
  line.too_long = false;
  line.length = 0;
  bool any = false;
  for (;;) {
    if (at_ == buf_.size() && !fill()) {
      if (!any) return false;
      line.number = ++number_;
      return true;   // the last line has no line ending
    }
    any = true;
    std::size_t end = at_;
    while (end < buf_.size() && buf_[end] != '\n' && buf_[end] != '\r') ++end;
    std::size_t n = end - at_;
    std::size_t room = line.length < max_line_ ? max_line_ - line.length : 0;
    line.text.append(buf_, at_, std::min(n, room));
    line.length += n;
    if (line.length > max_line_) line.too_long = true;
    if (end < buf_.size()) {
      after_cr_ = buf_[end] == '\r';
      at_ = end + 1;
      line.number = ++number_;
      return true;
    }
    at_ = end;
  }
}

std::size_t invalid_utf8_at(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size()) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      ++i;
      continue;
    }
    std::size_t len;
    std::uint32_t cp, min;
    if (c >= 0xC2 && c <= 0xDF) len = 2, cp = c & 0x1F, min = 0x80;
    else if (c >= 0xE0 && c <= 0xEF) len = 3, cp = c & 0x0F, min = 0x800;
    else if (c >= 0xF0 && c <= 0xF4) len = 4, cp = c & 0x07, min = 0x10000;
    else return i;
    if (i + len > s.size()) return i;
    for (std::size_t k = 1; k < len; ++k) {
      unsigned char d = static_cast<unsigned char>(s[i + k]);
      if ((d & 0xC0) != 0x80) return i;
      cp = (cp << 6) | (d & 0x3F);
    }
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return i;
    i += len;
  }
  return std::string_view::npos;
}

std::string json_text(const nlohmann::json& j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string json_text(const nlohmann::ordered_json& j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

// --- outputs -----------------------------------------------------------------------------------

namespace {

// The temporary file being written, for the signal handler (only async-signal-safe calls
// there: unlink, sigaction, raise).
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr std::size_t kNumCleanupSignals = sizeof(kCleanupSignals) / sizeof(kCleanupSignals[0]);
char g_pending_path[8192];
volatile std::sig_atomic_t g_pending = 0;
struct sigaction g_previous[kNumCleanupSignals];

extern "C" void remove_pending_and_reraise(int sig) {
  if (g_pending) {
    ::unlink(g_pending_path);
    g_pending = 0;
  }
  for (std::size_t i = 0; i < kNumCleanupSignals; ++i)
    if (kCleanupSignals[i] == sig) ::sigaction(sig, &g_previous[i], nullptr);
  // Delivered again when the handler returns (the signal is blocked until then), now with the
  // disposition the program had before: normally, termination by that signal.
  ::raise(sig);
}

// Blocks the cleanup signals for its lifetime, so the temporary file and its registration
// appear and disappear together.
class SignalsBlocked {
 public:
  SignalsBlocked() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : kCleanupSignals) sigaddset(&set, s);
    ::sigprocmask(SIG_BLOCK, &set, &old_);
  }
  ~SignalsBlocked() { ::sigprocmask(SIG_SETMASK, &old_, nullptr); }

 private:
  sigset_t old_;
};

// A temporary file beside the target: created with mkostemp (O_EXCL, mode 0600, an
// unpredictable name), registered for removal on a signal, removed by the destructor unless
// committed.
class PendingFile {
 public:
  PendingFile(const std::string& target, const std::string& shown) : shown_(shown) {
    std::filesystem::path t(target);
    std::string dir = t.parent_path().string();
    if (dir.empty()) dir = ".";
    std::string name = dir + "/." + t.filename().string() + ".tmp-XXXXXX";
    if (name.size() + 1 > sizeof(g_pending_path)) cannot_write(shown_, "the file name is too long");
    std::vector<char> tmpl(name.begin(), name.end());
    tmpl.push_back('\0');
    SignalsBlocked blocked;
    fd_ = ::mkostemp(tmpl.data(), O_CLOEXEC);
    if (fd_ < 0) cannot_write(shown_, errno_text(errno));
    path_ = tmpl.data();
    std::memcpy(g_pending_path, path_.c_str(), path_.size() + 1);
    struct sigaction sa {};
    sa.sa_handler = remove_pending_and_reraise;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;
    for (std::size_t i = 0; i < kNumCleanupSignals; ++i) ::sigaction(kCleanupSignals[i], &sa, &g_previous[i]);
    g_pending = 1;
  }

  ~PendingFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(path_.c_str());
    release();
  }

  void write(std::string_view data) {
    while (!data.empty()) {
      ssize_t n = ::write(fd_, data.data(), data.size());
      if (n < 0) {
        if (errno == EINTR) continue;
        cannot_write(shown_, errno_text(errno));
      }
      data.remove_prefix(static_cast<std::size_t>(n));
    }
  }

  const std::string& path() const { return path_; }

  void commit(const std::string& target, mode_t mode) {
    if (::fchmod(fd_, mode) != 0) cannot_write(shown_, errno_text(errno));
    if (::fsync(fd_) != 0) cannot_write(shown_, errno_text(errno));
    int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) cannot_write(shown_, errno_text(errno));
    SignalsBlocked blocked;
    if (!g_pending) cannot_write(shown_, "interrupted");   // a handler removed it already
    if (::rename(path_.c_str(), target.c_str()) != 0) cannot_write(shown_, errno_text(errno));
    committed_ = true;
  }

 private:
  void release() {
    SignalsBlocked blocked;
    if (!registered_) return;
    registered_ = false;
    g_pending = 0;
    for (std::size_t i = 0; i < kNumCleanupSignals; ++i) ::sigaction(kCleanupSignals[i], &g_previous[i], nullptr);
  }

  std::string shown_, path_;
  int fd_ = -1;
  bool committed_ = false, registered_ = true;
};

// The file a write to `path` replaces: symbolic links followed (also a dangling one: its
// target is created), refusing what is not a regular file.
std::string output_target(const std::string& path, struct stat* st, bool* exists) {
  if (path.empty()) cannot_write(path, "empty file name");
  std::string p = path;
  for (int hops = 0;; ++hops) {
    struct stat lst {};
    if (::lstat(p.c_str(), &lst) != 0) {
      if (errno != ENOENT) cannot_write(path, errno_text(errno));
      *exists = false;
      return p;
    }
    if (!S_ISLNK(lst.st_mode)) {
      if (S_ISDIR(lst.st_mode)) cannot_write(path, p == path ? "it is a directory" : "it links to a directory '" + p + "'");
      if (!S_ISREG(lst.st_mode))
        cannot_write(path, std::string(p == path ? "it is " : "it links to ") + file_kind(lst.st_mode) +
                               (p == path ? "" : " '" + p + "'") + "; only regular files are replaced");
      *st = lst;
      *exists = true;
      return p;
    }
    if (hops >= 40) cannot_write(path, "too many levels of symbolic links");
    std::vector<char> buf(static_cast<std::size_t>(std::max<off_t>(lst.st_size, 255)) + 2);
    ssize_t n = ::readlink(p.c_str(), buf.data(), buf.size() - 1);
    if (n < 0) cannot_write(path, errno_text(errno));
    std::filesystem::path link(std::string(buf.data(), static_cast<std::size_t>(n)));
    p = link.is_absolute() ? link.string() : (std::filesystem::path(p).parent_path() / link).string();
  }
}

mode_t new_file_mode() {
  mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

}  // namespace

void write_file_atomic(const std::string& path, const std::function<void(const ByteSink&)>& produce) {
  struct stat st {};
  bool exists = false;
  std::string target = output_target(path, &st, &exists);
  mode_t mode = exists ? (st.st_mode & 07777) : new_file_mode();
  PendingFile tmp(target, path);
  produce([&](std::string_view data) { tmp.write(data); });
  tmp.commit(target, mode);
}

void write_file_atomic_at(const std::string& path, const std::function<void(const std::string& temp_path)>& produce) {
  struct stat st {};
  bool exists = false;
  std::string target = output_target(path, &st, &exists);
  mode_t mode = exists ? (st.st_mode & 07777) : new_file_mode();
  PendingFile tmp(target, path);
  produce(tmp.path());
  tmp.commit(target, mode);
}

void write_file_atomic(const std::string& path, const std::string& content) {
  write_file_atomic(path, [&](const ByteSink& write) { write(content); });
}

void refuse_output_over_inputs(const std::string& output, const std::vector<std::string>& inputs,
                               const std::string& option) {
  struct stat out {};
  if (output.empty() || ::stat(output.c_str(), &out) != 0) return;   // a new file is no input
  for (const auto& in : inputs) {
    struct stat st {};
    if (::stat(in.c_str(), &st) == 0 && st.st_dev == out.st_dev && st.st_ino == out.st_ino)
      throw InputError({output, 0, 0}, "refusing to write '" + output + "': it is the input '" + in + "'; " + option +
                                           " must name a different file");
  }
}

std::vector<std::string> derivation_files(const std::vector<std::string>& inputs) {
  std::vector<std::string> out;
  for (const auto& in : inputs) {
    std::error_code ec;
    if (std::filesystem::is_directory(in, ec)) {
      std::vector<std::string> files;
      std::filesystem::directory_iterator it(in, ec);
      if (ec) throw InputError({in, 0, 0}, "cannot read directory '" + in + "': " + ec.message());
      for (; !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
        // Every *.dc entry that is not a directory: a FIFO or a dangling link named x.dc is then
        // reported when it is read, not skipped silently.
        std::error_code e2;
        if (it->path().extension() == ".dc" && !it->is_directory(e2)) files.push_back(it->path().string());
      }
      if (ec) throw InputError({in, 0, 0}, "cannot read directory '" + in + "': " + ec.message());
      std::sort(files.begin(), files.end());
      if (files.empty()) throw InputError({in, 0, 0}, "no .dc files in directory '" + in + "'");
      out.insert(out.end(), files.begin(), files.end());
    } else {
      out.push_back(in);
    }
  }
  return out;
}

}  // namespace dc
