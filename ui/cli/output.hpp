// Small file-output helpers shared by the commands: folders, files written atomically, file stems.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace nibrig::ui::cli {

// Creates the folder (and parents) or throws naming it.
void ensure_folder(const std::filesystem::path& folder);

// Creates the folder of `path` and writes `text` atomically (model/io/atomic_file.hpp), so a crash
// never leaves half a file.
void write_text_file(const std::filesystem::path& path, const std::string& text);
void write_json_file(const std::filesystem::path& path, const nlohmann::json& json);

// `--json FILE` on a command whose results are otherwise only printed: its numbers for a script
// (ui/cli/README.md, "Output files"); `holds` says what the file holds. Checked as file_to_write().
CLI::Option* add_json_option(CLI::App* command, std::filesystem::path& file,
                             const std::string& holds);
// Writes `numbers` to the --json file when one was given (after what was printed so far, so that
// a stream receives them in order) and confirms it with say_wrote.
void write_json_numbers(const std::filesystem::path& file, const nlohmann::json& numbers);

// The one confirmation every command prints after writing a file: "wrote <path>", so a script or
// a reader finds what was written the same way whichever command wrote it. On stdout, or on
// stderr when the file was a stream (-o /dev/stdout), to stay out of what was written.
void say_wrote(const std::filesystem::path& path);

// Check for an option naming a file to write (-o, --plot, --csv): what cannot be written (a
// folder, a block device, a socket: model/io/atomic_file.hpp) is refused while the command line
// is parsed, naming the option, instead of failing after the work.
CLI::Validator file_to_write();

// Refuses (CLI::ValidationError naming the option) an output option of `command` checked by
// file_to_write() that names the same file as any other option's value or positional argument:
// `space embed s.json cat.json -o cat.json` would replace the catalog it reads; and one of two
// such outputs naming the same file (`-o m.json --json m.json`).
void refuse_outputs_that_are_inputs(CLI::App& command);

// "arm_vero_1_office.csv.gz" -> "arm_vero_1_office"; a session folder -> its name.
std::string recording_stem(const std::filesystem::path& recording);

}  // namespace nibrig::ui::cli
