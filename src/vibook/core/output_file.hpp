/// \file output_file.hpp
/// \brief Output files that are never half-written under their final name.
///
/// Every file vibook writes goes through here. A path is checked before any work starts
/// (`check_output_path`): an existing regular file or a new name in a writable directory is
/// written to a temporary file beside it and renamed onto the final name only when everything
/// was written, flushed and closed without error. A character device or a FIFO (`/dev/null`,
/// a pipe) is written through, never replaced. A symbolic link, a directory, a block device,
/// a socket or a read-only file is refused. A failed write is an IoError (command line: exit
/// status 4), and the temporary file is removed.
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>

namespace vibook {

/// The directory a report path names ("rep/" is "rep").
std::filesystem::path report_directory(const std::string& dir);

/// Checks, before any work starts, that the directory `dir` may receive a report (an HTML page
/// with its files, written by the verify studies): a new name in a writable directory, an empty
/// directory, or an earlier report (index.html and verify.json), which is replaced. Throws
/// ArgumentError naming `arg` otherwise (a file, a symbolic link, a directory holding anything
/// else).
void check_report_directory(const std::string& dir, const std::string& arg);

/// How an output path will be written.
enum class OutputKind {
  standard_output,  ///< "-"
  replace,          ///< new path or regular file: temporary beside it, renamed at the end
  write_through,    ///< character device or FIFO: opened and written in place
};

/// Checks that `path` may be written, before any work starts; throws ArgumentError naming
/// `arg` otherwise. "-" means standard output when `allow_stdout`.
OutputKind check_output_path(const std::string& path, const std::string& arg,
                             bool allow_stdout = true);

/// One output file (see the file comment). Destroyed without commit(), it removes its
/// temporary file.
class OutputFile {
 public:
  /// Checks the path (ArgumentError naming `arg`) and opens the temporary file (IoError).
  OutputFile(const std::string& path, std::string arg, bool allow_stdout = true);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream();
  bool is_stdout() const { return kind_ == OutputKind::standard_output; }
  /// Flushes and closes, checks every write, renames the temporary onto the final path.
  /// Throws IoError naming the path on any failure (the temporary is then removed).
  void commit();
  /// After a failure of the computation: keeps what was written as PATH.partial (when that
  /// name may be written; otherwise the temporary is removed) and says where it is.
  std::string keep_partial();

 private:
  std::filesystem::path final_, tmp_;
  std::string arg_;
  OutputKind kind_;
  std::ofstream file_;
  bool done_ = false;
};

/// Writes `text` to `path` through an OutputFile (checked, temporary, renamed).
void write_output_file(const std::string& path, const std::string& text, const std::string& arg);

/// Flushes standard output and throws IoError if any write to it failed (a full disk, a
/// closed pipe): the command line checks this before it exits with status 0.
void check_standard_output();

/// A fresh directory beside `final_dir` (same parent, hidden name), for outputs that consist
/// of several files: fill it, then `commit_directory` renames it onto `final_dir`.
std::filesystem::path temporary_directory_for(const std::filesystem::path& final_dir);
/// Moves `tmp_dir`'s entries into `final_dir`: renames it when absent; into an existing
/// directory, each entry replaces its namesake and every other entry (a user's notes) is left
/// alone. A symbolic link or a non-directory at `final_dir`, or at one of our names an entry
/// of another kind, is refused (IoError) and left alone.
void commit_directory(const std::filesystem::path& tmp_dir, const std::filesystem::path& final_dir);

/// Removes a directory from temporary_directory_for that will not be committed (after a
/// failure).
void discard_temporary_directory(const std::filesystem::path& tmp_dir);

/// Records an output directory this process created (empty so far): remove_temporaries
/// removes it again while it is still empty.
void track_created_directory(const std::filesystem::path& dir);

/// Creates the output directory `dir` where it is missing (every level, each recorded with
/// track_created_directory, so that an interrupted command leaves none of them behind) and
/// checks that a file can be written in it. Throws ArgumentError naming `arg` otherwise.
void ensure_output_directory(const std::filesystem::path& dir, const std::string& arg);

/// Removes every temporary file and directory that exists now (written but not yet renamed
/// onto its final name), and the created output directories that are still empty. For a
/// signal that ends the process: the command line calls it from its signal thread. The
/// registry stays locked afterwards (a thread creating a temporary then waits until the
/// process ends): call it only right before the process ends.
void remove_temporaries() noexcept;

}  // namespace vibook
