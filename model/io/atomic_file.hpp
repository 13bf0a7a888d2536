// Writing an output file so that nothing is replaced that was not meant to be, and a reader never
// sees it half written. What the user named decides how:
//   - a regular file (or a new name): the content goes to a temporary file beside it, is flushed to
//     disk, and is renamed over it in one step;
//   - a symbolic link: the same, at the file the link points to; the link stays;
//   - a character device or a pipe (/dev/stdout, /dev/null, a FIFO): written to as a stream;
//   - anything else (a folder, a block device, a socket): refused before anything is written.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

namespace nibrig::model::io {

// What every writer throws when the file cannot be written (a folder in its place, no room, no
// permission): it names the file. A face tells it from bad input (the Python module: OSError).
class OutputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where an output named `named` goes.
struct OutputTarget {
  std::filesystem::path path;  // the file itself: a symbolic link followed to its end
  bool stream = false;         // a character device or a pipe: written in place, never renamed
};

// Throws std::runtime_error naming `named` when it is something that cannot be written, and
// OutputFileError when the file it would replace is an input of the running job (job_files.hpp).
OutputTarget output_target(const std::filesystem::path& named);

// A file an output names beside itself (the recipe and STLs beside a 3MF) must not be a link: the
// person named `named`, not what a link beside it points to (a catalog, once). Throws
// OutputFileError naming both.
void refuse_companion_link(const std::filesystem::path& companion, const std::filesystem::path& named);

// Where to write a temporary whole file for `target` (beside it, so the rename stays on one file
// system), unique per process and call.
std::filesystem::path temporary_beside(const OutputTarget& target);

// Moves a finished temporary file into place: renamed over a regular target, or copied into a
// stream and then removed. Throws naming the target; the temporary is removed on failure. Inside
// an OutputSet, a regular target's rename waits for the set's commit().
void commit_output(const std::filesystem::path& temporary, const OutputTarget& target);

// Files that appear together or not at all (a 3MF with its STLs, recipe and print sheet): while one
// lives on this thread, every finished output is held back as its temporary; commit() renames them
// all into place, and without commit() they are removed. A full disk or a refusal halfway through
// then leaves an earlier set whole, never new files beside old ones.
class OutputSet {
 public:
  OutputSet();
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Throws OutputFileError naming the target when a rename fails; those not yet renamed are removed.
  void commit();

  // For commit_output: holds a finished temporary back. Throws OutputFileError when two outputs of
  // the set are the same file.
  void hold(const std::filesystem::path& temporary, const std::filesystem::path& target);

 private:
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> held_;  // temporary, target
  OutputSet* outer_;
};

// Throws std::runtime_error naming the file and the system's reason when any step fails; the
// temporary file is removed then. A ".csv" file's text is first checked by check_csv_finite
// (finite_output.hpp): every table nibrig writes goes through here.
void write_file_atomically(const std::filesystem::path& target, std::string_view content);

}  // namespace nibrig::model::io
