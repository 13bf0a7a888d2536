#include "model/catalog/catalog_builder.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "model/catalog/tool_names.hpp"
#include "model/io/job_files.hpp"
#include "model/io/paper_friction.hpp"
#include "model/io/paper_recording.hpp"
#include "model/io/paper_vibration.hpp"
#include "model/io/rig_session.hpp"

namespace nibrig::model::catalog {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool is_csv(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  return ends_with(name, ".csv") || ends_with(name, ".csv.gz");
}

bool is_under(const std::filesystem::path& path, const std::string& folder) {
  for (const auto& part : path) {
    if (part == folder) return true;
  }
  return false;
}

}  // namespace

RecordingKind classify_recording(const std::filesystem::path& path) {
  if (std::filesystem::is_directory(path)) {
    if (std::filesystem::exists(path / "session.json")) return RecordingKind::session;
    throw std::runtime_error(path.string() +
                             ": a folder without session.json is not a rig session");
  }
  if (!std::filesystem::exists(path)) throw std::runtime_error(path.string() + ": no such file");
  const std::string name = path.filename().string();
  if (is_csv(path) && name.rfind("arm_", 0) == 0 && io::is_paper_vibration_file(path)) {
    return RecordingKind::paper_vibration;
  }
  if (is_csv(path) && (is_under(path, "friction") || name.find("N_") != std::string::npos)) {
    return RecordingKind::paper_friction;
  }
  throw std::runtime_error(path.string() +
                           ": not a recording nibrig knows (expected a rig session folder, a paper "
                           "friction file <tool>_<surface>_<load>N_<lever>_<rep>.csv[.gz] or an "
                           "accelerometer file arm_<tool>_<surface>.csv[.gz])");
}

RecordingKind classify_recording_by_content(const std::filesystem::path& path) {
  try {
    return classify_recording(path);
  } catch (const std::runtime_error&) {
    if (!is_csv(path) || !std::filesystem::is_regular_file(path)) throw;
  }
  return io::paper_format_from_header(path) == io::PaperFormat::friction
             ? RecordingKind::paper_friction
             : RecordingKind::paper_vibration;
}

FoundRecordings find_recordings(const std::filesystem::path& folder) {
  if (!std::filesystem::is_directory(folder)) {
    throw std::runtime_error(folder.string() + ": not a folder");
  }
  FoundRecordings found;
  std::vector<std::filesystem::path> candidates;
  for (auto it = std::filesystem::recursive_directory_iterator(folder);
       it != std::filesystem::recursive_directory_iterator(); ++it) {
    const auto& path = it->path();
    if (it->is_directory()) {
      if (std::filesystem::exists(path / "session.json")) {
        candidates.push_back(path);
        it.disable_recursion_pending();
      }
      continue;
    }
    if (is_csv(path)) candidates.push_back(path);
  }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& path : candidates) {
    // The artists' drawings are trajectories, not rig recordings: they drive the engine, not the
    // catalog.
    if (is_under(path, "drawing")) continue;
    try {
      found.files.push_back({path, classify_recording(path)});
      io::note_input(path);  // to be read: no output of this job may replace it
    } catch (const std::exception& e) {
      found.skipped.push_back(e.what());
    }
  }
  return found;
}

CatalogBuild build_catalog(const FoundRecordings& recordings,
                           const measure::ThresholdCurve& threshold, const AnalysisOptions& options,
                           unsigned threads,
                           const std::function<void(const std::filesystem::path&)>& on_done) {
  const std::size_t n = recordings.files.size();
  std::vector<std::optional<FrictionAnalysis>> friction(n);
  std::vector<std::optional<VibrationAnalysis>> vibration(n);
  std::vector<std::optional<SessionAnalysis>> sessions(n);
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;

  auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      {
        std::lock_guard lock(failure_mutex);
        if (failure) return;
      }
      const auto& file = recordings.files[i];
      try {
        switch (file.kind) {
          case RecordingKind::paper_friction:
            friction[i] = analyze_friction(io::read_paper_friction(file.path), options);
            break;
          case RecordingKind::paper_vibration:
            vibration[i] =
                analyze_vibration(io::read_paper_vibration(file.path), threshold, options);
            break;
          case RecordingKind::session:
            sessions[i] = analyze_session(io::read_rig_session(file.path), threshold, options);
            break;
        }
        // Inside the try: a caller's progress may stop the build by throwing (a cancellation), and
        // an exception leaving a worker thread would end the process.
        if (on_done) on_done(file.path);
      } catch (...) {
        std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        return;
      }
    }
  };
  threads =
      std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(std::max<std::size_t>(n, 1))));
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);

  CatalogBuild build;
  build.skipped = recordings.skipped;
  for (std::size_t i = 0; i < n; ++i) {
    if (sessions[i]) {
      if (sessions[i]->friction) friction[i] = std::move(sessions[i]->friction);
      if (sessions[i]->vibration) vibration[i] = std::move(sessions[i]->vibration);
    }
    if (friction[i]) build.friction.push_back(std::move(*friction[i]));
    if (vibration[i]) build.vibration.push_back(std::move(*vibration[i]));
  }

  // Pairings keyed by (tool, surface); a second recording of the same pair is kept apart in the
  // notes rather than averaged blindly, since repetitions differ in wear and lever setting.
  std::map<std::pair<std::string, std::string>, io::Pairing> pairings;
  std::map<std::string, io::ToolEntry> tools;
  std::map<std::string, io::SurfaceEntry> surfaces;
  auto pairing = [&](const std::string& tool, const std::string& surface) -> io::Pairing& {
    tools.try_emplace(tool, describe_tool(tool));
    surfaces.try_emplace(surface, describe_surface(surface));
    auto& p = pairings[{tool, surface}];
    p.tool = tool;
    p.surface = surface;
    return p;
  };
  for (const auto& f : build.friction) {
    auto& p = pairing(f.tool, f.surface);
    if (p.friction) {
      build.catalog.notes.push_back("second friction recording of " + f.tool + " on " + f.surface +
                                    " (" + f.source.filename().string() + ") not used; kept " +
                                    p.friction->provenance.source);
      continue;
    }
    p.friction = to_descriptor(f);
  }
  for (const auto& v : build.vibration) {
    auto& p = pairing(v.tool, v.surface);
    if (p.vibration) {
      build.catalog.notes.push_back("second vibration recording of " + v.tool + " on " + v.surface +
                                    " (" + v.source.filename().string() + ") not used");
      continue;
    }
    p.vibration = to_descriptor(v, threshold);
  }
  for (auto& [id, tool] : tools) build.catalog.tools.push_back(tool);
  for (auto& [id, surface] : surfaces) build.catalog.surfaces.push_back(surface);
  for (auto& [key, p] : pairings) build.catalog.pairings.push_back(std::move(p));
  for (const auto& s : recordings.skipped) build.catalog.notes.push_back("skipped " + s);
  const bool from_paper =
      std::any_of(recordings.files.begin(), recordings.files.end(),
                  [](const auto& f) { return f.kind != RecordingKind::session; });
  if (from_paper)
    build.catalog.citation =
        "M. Piovarci, D. I. W. Levin, D. M. Kaufman, P. Didyk, \"Perception-Aware Modeling and "
        "Fabrication of Digital Drawing Tools\", ACM Transactions on Graphics 37(4), SIGGRAPH "
        "2018; "
        "recordings from the authors' supplementary material";
  return build;
}

}  // namespace nibrig::model::catalog
