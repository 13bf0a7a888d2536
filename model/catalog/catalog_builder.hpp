// Every recording in a folder tree -> one tool catalog: finds the paper's friction and
// accelerometer files and our rig sessions, analyses them in parallel, and gathers the descriptors
// of each tool-surface pair with the provenance of every number.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "model/catalog/analysis.hpp"
#include "model/io/catalog_file.hpp"

namespace nibrig::model::catalog {

enum class RecordingKind { paper_friction, paper_vibration, session };

struct RecordingFile {
  std::filesystem::path path;
  RecordingKind kind;
};

struct FoundRecordings {
  std::vector<RecordingFile> files;  // sorted by path, so catalogs are reproducible
  std::vector<std::string> skipped;  // "<path>: <reason>" for files that are not recordings
};

// Each file found is noted as an input of the running job (io/job_files.hpp): an output named onto
// one is refused before the analysis starts, not after.
FoundRecordings find_recordings(const std::filesystem::path& folder);

// Which kind of recording a single path is; throws std::runtime_error naming the path if none.
RecordingKind classify_recording(const std::filesystem::path& path);
// The same for one file named on purpose (nibrig measure), so named anything: a CSV file whose
// name says neither kind is judged by its header line. Not for a folder walk, where every CSV
// file would then be taken for a recording.
RecordingKind classify_recording_by_content(const std::filesystem::path& path);

struct CatalogBuild {
  io::Catalog catalog;
  std::vector<FrictionAnalysis> friction;
  std::vector<VibrationAnalysis> vibration;
  std::vector<std::string> skipped;
};

// on_done is called (from worker threads, serialised by the caller if needed) as each file
// finishes; what it throws (a cancellation) stops the build and is rethrown here. A file that fails
// to read stops the build with its error: a catalog never silently lacks a file.
CatalogBuild build_catalog(const FoundRecordings& recordings,
                           const measure::ThresholdCurve& threshold, const AnalysisOptions& options,
                           unsigned threads,
                           const std::function<void(const std::filesystem::path&)>& on_done = {});

}  // namespace nibrig::model::catalog
