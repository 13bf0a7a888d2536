// The files one job reads, so that no file it writes replaces one of them through any name: the
// output a person named, a name derived from it (the recipe beside a 3MF), or a link to an input.
// A face marks where a job begins and ends (JobFiles: a whole `nibrig` command, one Python call);
// every reader notes the files it opens, and output_target (atomic_file.hpp), which every writer
// goes through, refuses a target among them.
#pragma once

#include <filesystem>

namespace nibrig::model::io {

// While one lives (on any thread), files read are noted and outputs checked against them. The notes
// are forgotten when the last one ends, so that one Python call's inputs do not bind the next.
class JobFiles {
 public:
  JobFiles();
  ~JobFiles();
  JobFiles(const JobFiles&) = delete;
  JobFiles& operator=(const JobFiles&) = delete;
};

// A reader opened `file` (nothing outside a job). A file this job wrote itself is not an input:
// reading back what was just written does not forbid writing it again.
void note_input(const std::filesystem::path& file);

// A writer put its output at `file` (its final name, after links).
void note_output(const std::filesystem::path& file);

// `file`, read by this job, is to be replaced on purpose (a lab's material recalibrated with
// replace): no longer an input. Nothing outside a job, or for a file not read.
void release_input(const std::filesystem::path& file);

// Throws OutputFileError when `target`, the file an output named `named` would replace, is a file
// this job read: the message names both.
void refuse_replacing_input(const std::filesystem::path& named,
                            const std::filesystem::path& target);

}  // namespace nibrig::model::io
