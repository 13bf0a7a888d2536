// What a process stopped by Ctrl-C, a hang-up or a termination must not leave behind: the
// temporary files and work folders of outputs not yet complete (a 99 MB `r.wav.tmp-PID` after an
// hour's render was stopped). Writers track them while they exist; a face that lets these signals
// end the process (the command line) installs the handler that removes them first.
#pragma once

#include <filesystem>

namespace nibrig::model::io {

// `path` (a file, or a folder and all in it) is removed if a handled signal ends the process
// before untrack_temporary. Paths longer than PATH_MAX, or more than the table holds at once, are
// not tracked (the writer still removes them on every other way out).
void track_temporary(const std::filesystem::path& path);
void untrack_temporary(const std::filesystem::path& path);

// SIGINT, SIGTERM and SIGHUP remove what is tracked, then end the process as the signal would
// have (exit status 128 + signal to a shell). The handler does only async-signal-safe calls.
void remove_temporaries_on_signals();

// How many paths are tracked now (for tests).
int tracked_temporaries();

}  // namespace nibrig::model::io
