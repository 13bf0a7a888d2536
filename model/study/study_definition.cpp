#include "model/study/study_definition.hpp"

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/bounded_read.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/text_lines.hpp"
#include "model/io/finite_output.hpp"

namespace nibrig::model::study {
namespace {

namespace jf = io::json_fields;
using nlohmann::json;

constexpr const char* kStudyFormat = "nibrig-study";
constexpr long long kStudyVersion = 1;
constexpr long long kStudyMaxCount = std::numeric_limits<int>::max();

std::size_t study_count(const json& object, const std::string& key,
                        const std::filesystem::path& file) {
  return static_cast<std::size_t>(
      jf::as_integer(jf::member(object, key, file, ""), file, key, 0, kStudyMaxCount));
}

// A study's instructions and consent texts; a missing one is empty (the bundled text is used).
constexpr std::size_t kMaxStudyTextBytes = std::size_t{1} << 20;

std::string read_study_text(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return {};
  return io::read_bounded_file(file, kMaxStudyTextBytes, "a study text",
                               "the bundled ones are a few KiB");
}

}  // namespace

const char* mode_name(StudyMode mode) {
  switch (mode) {
    case StudyMode::actuator: return "actuator";
    case StudyMode::rig: return "rig";
    case StudyMode::validation: return "validation";
  }
  return "?";
}

const char* plan_name(PlanKind plan) {
  switch (plan) {
    case PlanKind::two_stage: return "two-stage";
    case PlanKind::adaptive: return "adaptive";
    case PlanKind::file: return "file";
  }
  return "?";
}

std::optional<StudyMode> parse_mode(const std::string& text) {
  for (StudyMode m : {StudyMode::actuator, StudyMode::rig, StudyMode::validation})
    if (text == mode_name(m)) return m;
  return std::nullopt;
}

std::optional<PlanKind> parse_plan(const std::string& text) {
  for (PlanKind p : {PlanKind::two_stage, PlanKind::adaptive, PlanKind::file})
    if (text == plan_name(p)) return p;
  return std::nullopt;
}

void validate(const StudyDefinition& d) {
  const std::size_t n = d.stimuli.size();
  if (n < 3)
    throw std::invalid_argument("a study needs at least 3 stimuli, found " + std::to_string(n));
  std::set<std::string> names;
  for (const auto& s : d.stimuli) {
    if (s.name.empty() || s.name.find_first_of(",\n\r") != std::string::npos)
      throw std::invalid_argument("stimulus name '" + s.name +
                                  "' is empty or holds a ',' or a line break");
    if (!names.insert(s.name).second)
      throw std::invalid_argument("stimulus '" + s.name + "' is listed twice");
  }
  if (d.dims < 1 || d.dims + 1 > n)
    throw std::invalid_argument("dims must be between 1 and " + std::to_string(n - 1) + " for " +
                                std::to_string(n) + " stimuli, found " + std::to_string(d.dims));
  if (d.plan == PlanKind::file && d.listed_trials.empty())
    throw std::invalid_argument("a study with a listed plan needs at least one trial");
  for (std::size_t i = 0; i < d.listed_trials.size(); ++i) {
    const space::Trial& t = d.listed_trials[i];
    if (t.reference >= n || t.left >= n || t.right >= n || t.reference == t.left ||
        t.reference == t.right || t.left == t.right || t.stage < 1)
      throw std::invalid_argument("listed trial " + std::to_string(i + 1) +
                                  " names a stimulus out of range, one twice, or a stage < 1");
  }
}

void write_study_file(const std::filesystem::path& file, const StudyDefinition& d) {
  validate(d);
  json stimuli = json::array();
  for (const auto& s : d.stimuli)
    stimuli.push_back({{"name", s.name}, {"tool", s.tool}, {"surface", s.surface}});
  json listed = json::array();
  for (const auto& t : d.listed_trials)
    listed.push_back({{"reference", t.reference}, {"left", t.left}, {"right", t.right},
                      {"stage", t.stage}});
  const json j = {{"format", kStudyFormat},
                  {"version", kStudyVersion},
                  {"stimuli", stimuli},
                  {"mode", mode_name(d.mode)},
                  {"plan", plan_name(d.plan)},
                  {"listed_trials", listed},
                  {"trials", d.trials},
                  {"practice", d.practice},
                  {"break_every", d.break_every},
                  {"dims", d.dims}};
  io::write_file_atomically(file, io::json_text(j, file));
}

StudyDefinition read_study_file(const std::filesystem::path& file) {
  const json j = jf::parse_file(file);
  jf::as_object(j, file, "");
  jf::check_format_and_version(j, file, kStudyFormat, kStudyVersion);
  StudyDefinition d;
  const json& stimuli = jf::as_array(jf::member(j, "stimuli", file, ""), file, "stimuli");
  for (std::size_t i = 0; i < stimuli.size(); ++i) {
    const std::string path = jf::element_path("stimuli", i);
    jf::as_object(stimuli[i], file, path);
    d.stimuli.push_back({jf::string_member(stimuli[i], "name", file, path),
                         jf::string_member(stimuli[i], "tool", file, path),
                         jf::string_member(stimuli[i], "surface", file, path)});
  }
  const std::string mode = jf::string_member(j, "mode", file, "");
  const std::string plan = jf::string_member(j, "plan", file, "");
  if (!parse_mode(mode))
    throw io::FormatError(file, jf::place("mode"),
                          "expected actuator, rig or validation, found " + io::in_quotes(mode));
  if (!parse_plan(plan))
    throw io::FormatError(file, jf::place("plan"),
                          "expected two-stage, adaptive or file, found " + io::in_quotes(plan));
  d.mode = *parse_mode(mode);
  d.plan = *parse_plan(plan);
  const json& listed = jf::as_array(jf::member(j, "listed_trials", file, ""), file, "listed_trials");
  const long long last = static_cast<long long>(d.stimuli.size()) - 1;
  for (std::size_t i = 0; i < listed.size(); ++i) {
    const std::string path = jf::element_path("listed_trials", i);
    jf::as_object(listed[i], file, path);
    auto index = [&](const char* key, long long min, long long max) {
      return jf::as_integer(jf::member(listed[i], key, file, path), file,
                            jf::member_path(path, key), min, max);
    };
    d.listed_trials.push_back({static_cast<std::size_t>(index("reference", 0, last)),
                               static_cast<std::size_t>(index("left", 0, last)),
                               static_cast<std::size_t>(index("right", 0, last)),
                               static_cast<int>(index("stage", 1, 1000))});
  }
  d.trials = study_count(j, "trials", file);
  d.practice = study_count(j, "practice", file);
  d.break_every = study_count(j, "break_every", file);
  d.dims = study_count(j, "dims", file);
  try {
    validate(d);
  } catch (const std::invalid_argument& e) {
    throw io::FormatError(file, "", e.what());
  }
  return d;
}

std::optional<std::string> study_difference(const StudyDefinition& existing,
                                            const StudyDefinition& given) {
  if (existing.stimuli.size() != given.stimuli.size())
    return std::to_string(given.stimuli.size()) + " stimuli here but " +
           std::to_string(existing.stimuli.size()) + " in the study";
  for (std::size_t i = 0; i < existing.stimuli.size(); ++i) {
    const Stimulus& a = existing.stimuli[i];
    const Stimulus& b = given.stimuli[i];
    if (a.name != b.name || a.tool != b.tool || a.surface != b.surface)
      return "stimulus " + std::to_string(i + 1) + " is '" + b.name + "' (" + pairing_of(b) +
             ") here but '" + a.name + "' (" + pairing_of(a) + ") in the study";
  }
  if (existing.mode != given.mode)
    return std::string("mode ") + mode_name(given.mode) + " here but " + mode_name(existing.mode) +
           " in the study";
  if (existing.plan != given.plan)
    return std::string("plan ") + plan_name(given.plan) + " here but " + plan_name(existing.plan) +
           " in the study";
  if (existing.trials != given.trials)
    return std::to_string(given.trials) + " trials here but " + std::to_string(existing.trials) +
           " in the study (0: the plan's own size)";
  if (existing.listed_trials.size() != given.listed_trials.size())
    return "the listed plan differs from the study's";
  for (std::size_t i = 0; i < existing.listed_trials.size(); ++i) {
    const space::Trial& a = existing.listed_trials[i];
    const space::Trial& b = given.listed_trials[i];
    if (a.reference != b.reference || a.left != b.left || a.right != b.right || a.stage != b.stage)
      return "listed trial " + std::to_string(i + 1) + " differs from the study's";
  }
  if (existing.practice != given.practice || existing.break_every != given.break_every ||
      existing.dims != given.dims)
    return "practice trials, breaks or dims differ from the study's";
  return std::nullopt;
}

StudyTexts read_study_texts(const std::filesystem::path& folder) {
  return {read_study_text(folder / kInstructionsFile), read_study_text(folder / kConsentFile)};
}

}  // namespace nibrig::model::study
