// Output files (output_file.hpp): checked before work, written beside, renamed at the end.
#include "vibook/core/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <vector>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <mutex>
#include <system_error>
#include <type_traits>

#include "vibook/core/errors.hpp"

namespace fs = std::filesystem;

namespace vibook {

namespace {

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// The temporaries that exist now (remove_temporaries, called when a signal ends the process).
struct Temporaries {
  std::mutex mutex;
  std::vector<fs::path> paths;         // temporary files and directories: removed whole
  std::vector<fs::path> created_dirs;  // output directories we created: removed when empty
};
Temporaries& temporaries() {
  static Temporaries t;
  return t;
}
// Creates a temporary (mkstemp or mkdtemp on `tmpl`) and records it in one step under the
// registry's lock, so that remove_temporaries never misses one created while it runs.
template <class Create>
auto create_tracked(std::string& tmpl, Create create) {
  auto& t = temporaries();
  const std::lock_guard lock(t.mutex);
  const auto result = create(tmpl.data());
  const bool ok = [&] {
    if constexpr (std::is_pointer_v<decltype(result)>)
      return result != nullptr;
    else
      return result >= 0;
  }();
  if (ok) t.paths.emplace_back(tmpl);
  return result;
}
void untrack(const fs::path& p) {
  auto& t = temporaries();
  const std::lock_guard lock(t.mutex);
  std::erase(t.paths, p);
}
// Removes a temporary file or directory and forgets it.
void discard(const fs::path& p) {
  std::error_code ec;
  fs::remove_all(p, ec);
  untrack(p);
}

std::string last_error() { return std::strerror(errno); }

fs::path parent_of(const fs::path& p) {
  const fs::path d = p.parent_path();
  return d.empty() ? fs::path(".") : d;
}

// The process's umask, read once (umask() both reads and sets it, so it is not read again
// while threads may be writing files).
mode_t process_umask() {
  static const mode_t m = [] {
    const mode_t old = ::umask(0);
    ::umask(old);
    return old;
  }();
  return m;
}

void check_directory(const fs::path& dir, const std::string& arg) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw ArgumentError(arg, "directory " + quoted(dir) + " does not exist");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw ArgumentError(arg, "directory " + quoted(dir) + " is not writable");
}

}  // namespace

OutputKind check_output_path(const std::string& path, const std::string& arg, bool allow_stdout) {
  if (path.empty()) throw ArgumentError(arg, "the output path is empty");
  if (path == "-") {
    if (!allow_stdout) throw ArgumentError(arg, "standard output ('-') is not accepted here");
    return OutputKind::standard_output;
  }
  const fs::path p(path);
  struct stat st {};
  if (::lstat(p.c_str(), &st) != 0) {
    if (errno != ENOENT)
      throw ArgumentError(arg, "cannot access " + quoted(p) + ": " + last_error());
    if (!path.empty() && path.back() == '/')
      throw ArgumentError(arg, quoted(p) + " names a directory, not a file");
    check_directory(parent_of(p), arg);
    return OutputKind::replace;
  }
  if (S_ISLNK(st.st_mode)) {
    struct stat target {};
    if (::stat(p.c_str(), &target) == 0 && (S_ISCHR(target.st_mode) || S_ISFIFO(target.st_mode)))
      return OutputKind::write_through;
    throw ArgumentError(arg, quoted(p) +
                                 " is a symbolic link; vibook does not replace links (give the "
                                 "path of its target)");
  }
  if (S_ISDIR(st.st_mode)) throw ArgumentError(arg, quoted(p) + " is a directory");
  if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return OutputKind::write_through;
  if (!S_ISREG(st.st_mode))
    throw ArgumentError(arg, quoted(p) + " is not a regular file (a block device or a socket)");
  if ((st.st_mode & 0222) == 0) throw ArgumentError(arg, quoted(p) + " is read-only");
  check_directory(parent_of(p), arg);
  return OutputKind::replace;
}

OutputFile::OutputFile(const std::string& path, std::string arg, bool allow_stdout)
    : final_(path), arg_(std::move(arg)), kind_(check_output_path(path, arg_, allow_stdout)) {
  if (kind_ == OutputKind::standard_output) return;
  if (kind_ == OutputKind::write_through) {
    file_.open(final_, std::ios::out | std::ios::binary);
    if (!file_) throw IoError("cannot open " + quoted(final_) + " for writing: " + last_error());
    return;
  }
  // A unique hidden name in the same directory (so that rename is atomic), with the mode the
  // final file will have: the existing file's, or the usual one for a new file.
  std::string tmpl = (parent_of(final_) / ("." + final_.filename().string() + ".XXXXXX")).string();
  const int fd = create_tracked(tmpl, ::mkstemp);
  if (fd < 0)
    throw IoError("cannot create a temporary file beside " + quoted(final_) + ": " + last_error());
  tmp_ = tmpl;
  struct stat st {};
  const mode_t mode =
      ::stat(final_.c_str(), &st) == 0 ? (st.st_mode & 07777) : (0666 & ~process_umask());
  if (::fchmod(fd, mode) != 0 || ::close(fd) != 0) {
    discard(tmp_);
    throw IoError("cannot prepare " + quoted(tmp_) + ": " + last_error());
  }
  file_.open(tmp_, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!file_) {
    discard(tmp_);
    throw IoError("cannot open " + quoted(tmp_) + " for writing: " + last_error());
  }
}

OutputFile::~OutputFile() {
  if (kind_ != OutputKind::replace) return;
  if (!done_) {
    file_.close();
    discard(tmp_);
  }
  untrack(tmp_);
}

std::ostream& OutputFile::stream() {
  return kind_ == OutputKind::standard_output ? std::cout : static_cast<std::ostream&>(file_);
}

void OutputFile::commit() {
  done_ = true;
  if (kind_ == OutputKind::standard_output) {
    check_standard_output();
    return;
  }
  errno = 0;
  file_.flush();
  file_.close();
  const bool failed = file_.fail();
  const std::string why = errno != 0 ? last_error() : "write failed";
  if (kind_ == OutputKind::write_through) {
    if (failed) throw IoError("cannot write " + quoted(final_) + ": " + why);
    return;
  }
  if (failed) {
    discard(tmp_);
    throw IoError("cannot write " + quoted(final_) + ": " + why + " (nothing was replaced)");
  }
  // The final name must still be a regular file or absent: never rename over anything else.
  struct stat st {};
  if (::lstat(final_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    discard(tmp_);
    throw IoError(quoted(final_) +
                  " stopped being a regular file while vibook ran; nothing was "
                  "replaced");
  }
  if (::rename(tmp_.c_str(), final_.c_str()) != 0) {
    const std::string e = last_error();
    discard(tmp_);
    throw IoError("cannot rename " + quoted(tmp_) + " to " + quoted(final_) + ": " + e);
  }
}

std::string OutputFile::keep_partial() {
  done_ = true;
  if (kind_ == OutputKind::standard_output) {
    std::cout.flush();
    return "the rows before it were written to standard output";
  }
  file_.flush();
  file_.close();
  if (kind_ == OutputKind::write_through)
    return "the rows before it were written to " + quoted(final_);
  fs::path partial = final_;
  partial += ".partial";
  bool kept = false;
  try {
    kept = !file_.fail() &&
           check_output_path(partial.string(), arg_, false) == OutputKind::replace &&
           ::rename(tmp_.c_str(), partial.c_str()) == 0;
  } catch (const ArgumentError&) {
    kept = false;
  }
  if (kept) return "the rows before it are in " + quoted(partial) + " (incomplete)";
  discard(tmp_);
  return "no partial output was kept";
}

void write_output_file(const std::string& path, const std::string& text, const std::string& arg) {
  OutputFile f(path, arg);
  f.stream() << text;
  f.commit();
}

void check_standard_output() {
  errno = 0;
  std::cout.flush();
  const bool bad = std::fflush(stdout) != 0 || std::ferror(stdout) != 0 || !std::cout;
  if (bad) {
    const std::string why = errno != 0 ? last_error() : "write failed";
    std::clearerr(stdout);
    std::cout.clear();
    throw IoError("standard output: " + why);
  }
}

fs::path temporary_directory_for(const fs::path& final_dir) {
  const fs::path parent = parent_of(final_dir);
  std::error_code ec;
  fs::create_directories(parent, ec);
  std::string tmpl = (parent / ("." + final_dir.filename().string() + ".tmp-XXXXXX")).string();
  if (create_tracked(tmpl, ::mkdtemp) == nullptr)
    throw IoError("cannot create a temporary directory in " + quoted(parent) + ": " + last_error());
  // mkdtemp makes it private (0700); the final directory gets the usual mode.
  if (::chmod(tmpl.c_str(), 0777 & ~process_umask()) != 0) {
    const std::string e = last_error();
    discard(tmpl);
    throw IoError("cannot set the mode of " + quoted(fs::path(tmpl)) + ": " + e);
  }
  return tmpl;
}

void commit_directory(const fs::path& tmp_dir, const fs::path& final_dir) {
  struct stat st {};
  std::error_code ec;
  if (::lstat(final_dir.c_str(), &st) != 0) {
    if (::rename(tmp_dir.c_str(), final_dir.c_str()) != 0)
      throw IoError("cannot rename the new output onto " + quoted(final_dir) + ": " + last_error());
    untrack(tmp_dir);
    return;
  }
  if (!S_ISDIR(st.st_mode))
    throw IoError(quoted(final_dir) +
                  " exists and is not a directory (or is a link); nothing was written there");
  // An existing directory: each of our entries replaces its namesake (a file by rename, so
  // atomically); anything else in it is the user's and stays. Entries in sorted order, so a
  // failure part-way is reproducible.
  std::vector<fs::path> ours;
  for (const auto& e : fs::directory_iterator(tmp_dir)) ours.push_back(e.path());
  std::sort(ours.begin(), ours.end());
  for (const auto& from : ours) {
    const fs::path to = final_dir / from.filename();
    struct stat ft {
    }, tt{};
    if (::lstat(from.c_str(), &ft) != 0)
      throw IoError("cannot read the new output " + quoted(from) + ": " + last_error());
    if (::lstat(to.c_str(), &tt) == 0) {
      const bool same_kind = S_ISDIR(ft.st_mode) ? S_ISDIR(tt.st_mode) : S_ISREG(tt.st_mode);
      if (!same_kind)
        throw IoError(quoted(to) + " exists and is not a " +
                      (S_ISDIR(ft.st_mode) ? "directory" : "regular file") +
                      " (a link, a device, or the other kind); it was left alone and the new " +
                      "output was not written");
      if (S_ISDIR(tt.st_mode)) {
        fs::remove_all(to, ec);
        if (ec) throw IoError("cannot replace " + quoted(to) + ": " + ec.message());
      }
    }
    if (::rename(from.c_str(), to.c_str()) != 0)
      throw IoError("cannot write " + quoted(to) + ": " + last_error());
  }
  discard(tmp_dir);
}

void discard_temporary_directory(const fs::path& tmp_dir) { discard(tmp_dir); }

void track_created_directory(const fs::path& dir) {
  auto& t = temporaries();
  const std::lock_guard lock(t.mutex);
  t.created_dirs.push_back(dir);
}

void ensure_output_directory(const fs::path& dir, const std::string& arg) {
  std::error_code ec;
  std::vector<fs::path> created;
  for (fs::path p = fs::absolute(dir, ec).lexically_normal(); !p.empty() && !fs::exists(p, ec);
       p = p.parent_path()) {
    created.push_back(p);
    if (p == p.parent_path()) break;
  }
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw ArgumentError(arg, "cannot create directory '" + dir.string() + "'");
  for (auto it = created.rbegin(); it != created.rend(); ++it) track_created_directory(*it);
  const fs::path probe = dir / ".vibook-write-test";
  std::ofstream f(probe);
  if (!f) throw ArgumentError(arg, "directory '" + dir.string() + "' is not writable");
  f.close();
  fs::remove(probe, ec);
}

void remove_temporaries() noexcept {
  auto& t = temporaries();
  // Locked for good: the process ends next, and no thread may create a temporary after this.
  t.mutex.lock();
  for (const auto& p : t.paths) {
    // Another thread (or gnuplot) may still be writing into a temporary directory: retry
    // until it is gone, for at most about a second.
    std::error_code ec;
    for (int attempt = 0; attempt < 50; ++attempt) {
      fs::remove_all(p, ec);
      if (!fs::exists(fs::symlink_status(p, ec))) break;
      ::usleep(20000);
    }
  }
  t.paths.clear();
  // Deepest first; rmdir removes only an empty directory, so nothing anyone put there goes.
  for (auto it = t.created_dirs.rbegin(); it != t.created_dirs.rend(); ++it) ::rmdir(it->c_str());
  t.created_dirs.clear();
}  // t.mutex stays locked (see above)

}  // namespace vibook

namespace vibook {

std::filesystem::path report_directory(const std::string& dir) {
  std::filesystem::path d = std::filesystem::path(dir).lexically_normal();
  if (d.filename().empty()) d = d.parent_path();  // "rep/"
  return d;
}

void check_report_directory(const std::string& dir, const std::string& arg) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (dir.empty()) throw ArgumentError(arg, "is empty");
  const fs::path d = report_directory(dir);
  if (d.empty() || d.filename() == "." || d.filename() == "..")
    throw ArgumentError(arg, "'" + dir + "' does not name a new directory");
  const auto st = fs::symlink_status(d, ec);
  if (fs::exists(st)) {
    if (fs::is_symlink(st) || !fs::is_directory(st))
      throw ArgumentError(arg, "'" + dir + "' exists and is not a directory");
    const bool empty = fs::is_empty(d, ec);
    if (!empty && !(fs::exists(d / "index.html") && fs::exists(d / "verify.json")))
      throw ArgumentError(arg, "'" + dir +
                                   "' exists and is not an earlier report (index.html and "
                                   "verify.json); give a new name");
  }
  const fs::path parent = d.has_parent_path() ? d.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec) || ::access(parent.c_str(), W_OK) != 0)
    throw ArgumentError(
        arg, "cannot create '" + dir + "': '" + parent.string() + "' is not a writable directory");
}

}  // namespace vibook
