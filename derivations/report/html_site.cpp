// The site folder of `derivcheck html` (html.hpp): index.html and a copy of KaTeX, built in a
// temporary folder beside the target and swapped in whole.
#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "derivations/report/html.hpp"
#include "derivations/syntax/io.hpp"

namespace dc {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void site_error(const std::string& dir, const std::string& what) {
  throw InputError({dir, 0, 0}, what);
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The files of the KaTeX copy, relative to the KaTeX folder: the script, its style sheet, the
// auto-render extension and every font the style sheet names (fonts/, sorted).
std::vector<std::string> katex_files(const std::string& katex_dir) {
  const std::vector<std::string> needed = {"katex.min.css", "katex.min.js", "contrib/auto-render.js"};
  std::vector<std::string> files;
  for (const auto& f : needed) {
    std::error_code ec;
    if (!fs::is_regular_file(fs::path(katex_dir) / f, ec))
      site_error(katex_dir, "KaTeX not found: no '" + f + "' in '" + katex_dir +
                                "' (install Debian's libjs-katex, or pass --katex with the folder holding KaTeX)");
    files.push_back(f);
  }
  std::vector<std::string> fonts;
  std::error_code ec;
  for (fs::directory_iterator it(fs::path(katex_dir) / "fonts", ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code e2;
    if (it->is_regular_file(e2)) fonts.push_back("fonts/" + it->path().filename().string());
  }
  if (fonts.empty())
    site_error(katex_dir, "KaTeX fonts not found in '" + katex_dir + "/fonts' (Debian's fonts-katex provides them)");
  std::sort(fonts.begin(), fonts.end());
  files.insert(files.end(), fonts.begin(), fonts.end());
  return files;
}

// Removes the temporary folder unless it was renamed into place.
struct TempFolder {
  std::string path;
  bool keep = false;
  ~TempFolder() {
    if (!path.empty() && !keep) {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  }
};

void put(const fs::path& file, const std::string& bytes, const std::string& shown) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) site_error(shown, "cannot write '" + file.string() + "'");
}

}  // namespace

void check_html_site_target(const std::string& dir) {
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(dir, ec);
  if (!fs::exists(st)) return;
  if (!fs::is_directory(st))
    site_error(dir, "refusing to write the site to '" + dir + "': it exists and is not a folder");
  std::vector<std::string> foreign;
  bool ours = false;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name == "index.html") {
      std::ifstream in(it->path(), std::ios::binary);
      std::string head(kHtmlGeneratorLine.size(), '\0');
      in.read(head.data(), static_cast<std::streamsize>(head.size()));
      ours = in && head == kHtmlGeneratorLine;
      if (!ours) foreign.push_back(name);
    } else if (name != "katex") {
      foreign.push_back(name);
    }
  }
  if (ec) site_error(dir, "cannot read folder '" + dir + "': " + ec.message());
  std::sort(foreign.begin(), foreign.end());
  if (!foreign.empty())
    site_error(dir, "refusing to replace '" + dir + "': it holds '" + foreign.front() +
                        "', which derivcheck html did not write; name a new or empty folder, or a site html wrote");
}

void check_html_katex(const std::string& katex_dir) { katex_files(katex_dir); }

void write_html_site(const std::string& dir, const std::string& index_html, const std::string& katex_dir) {
  check_html_site_target(dir);
  const std::vector<std::string> files = katex_files(katex_dir);
  fs::path target = fs::path(dir);
  if (target.filename().empty()) target = target.parent_path();   // "site/"
  fs::path parent = target.parent_path();
  if (parent.empty()) parent = ".";
  std::string name = ".";   // (not "." + string: GCC 12 warns a false -Wrestrict on it)
  name += target.filename().string();
  name += ".tmp-XXXXXX";
  const std::string tmpl = (parent / name).string();
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back('\0');
  if (::mkdtemp(buf.data()) == nullptr)
    site_error(dir, "cannot write the site '" + dir + "': " + std::strerror(errno));
  TempFolder tmp{buf.data()};
  const mode_t mask = ::umask(0);   // mkdtemp makes the folder 0700; a site is read by others
  ::umask(mask);
  ::chmod(tmp.path.c_str(), 0777 & ~mask);
  put(fs::path(tmp.path) / "index.html", index_html, dir);
  std::error_code ec;
  for (const auto& f : files) {
    const fs::path to = fs::path(tmp.path) / "katex" / f;
    fs::create_directories(to.parent_path(), ec);
    if (ec) site_error(dir, "cannot write the site '" + dir + "': " + ec.message());
    put(to, read_bytes(fs::path(katex_dir) / f), dir);
  }
  // Into place: a new folder is renamed; an old site (or an empty folder) is swapped with the
  // new one in one step (renameat2 RENAME_EXCHANGE), then removed.
  check_html_site_target(dir);
  if (!fs::exists(fs::symlink_status(target, ec))) {
    if (::rename(tmp.path.c_str(), target.c_str()) != 0)
      site_error(dir, "cannot write the site '" + dir + "': " + std::strerror(errno));
    tmp.keep = true;
    return;
  }
  if (::renameat2(AT_FDCWD, tmp.path.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) != 0) {
    // a file system without the exchange: the old folder aside, the new one in, the old removed
    std::string aside = tmp.path;
    aside += ".old";
    if (::rename(target.c_str(), aside.c_str()) != 0)
      site_error(dir, "cannot replace the site '" + dir + "': " + std::strerror(errno));
    if (::rename(tmp.path.c_str(), target.c_str()) != 0) {
      const int err = errno;
      ::rename(aside.c_str(), target.c_str());
      site_error(dir, "cannot replace the site '" + dir + "': " + std::strerror(err));
    }
    fs::remove_all(aside, ec);
    tmp.keep = true;
    return;
  }
  // tmp.path now names the old site; the destructor removes it
}

}  // namespace dc
