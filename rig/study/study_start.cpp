#include "rig/study/study_start.hpp"

#include <utility>

#include "model/io/bundled_assets.hpp"
#include "rig/study/actuator_presenter.hpp"

namespace nibrig::rig {
namespace {

namespace study = model::study;
using Field = StudyStartRefused::Field;

std::filesystem::path study_text_or_bundled(const std::filesystem::path& given,
                                            const char* bundled) {
  return given.empty() ? model::io::asset(std::filesystem::path("experiment") / bundled) : given;
}

}  // namespace

StudyStartRefused::StudyStartRefused(Field field, const std::string& what)
    : std::invalid_argument(what), field_(field) {}

const char* field_name(StudyStartRefused::Field field) {
  switch (field) {
    case Field::participant:
      return "participant";
    case Field::definition:
      return "definition";
    case Field::folder:
      return "folder";
    case Field::stimulus:
      return "stimulus";
    case Field::rig:
      return "rig";
  }
  return "?";
}

StudyStart::StudyStart(StudyStartRequest request) : request_(std::move(request)) {
  const study::StudySettings& s = request_.settings;
  const std::filesystem::path study_file = s.study / study::kStudyFile;
  const bool study_exists = std::filesystem::exists(study_file);

  // The study: the one given, which must be the folder's when there is one; or the folder's own.
  if (request_.definition) {
    try {
      study::validate(*request_.definition);
    } catch (const std::invalid_argument& e) {
      throw StudyStartRefused(Field::definition, e.what());
    }
    definition_ = *request_.definition;
    if (study_exists)
      if (const auto difference =
              study::study_difference(study::read_study_file(study_file), definition_))
        throw StudyStartRefused(Field::folder, s.study.string() +
                                                   " holds another study: " + *difference +
                                                   "; use another folder for a new study");
  } else if (study_exists) {
    definition_ = study::read_study_file(study_file);
  } else if (s.resume) {
    throw StudyStartRefused(
        Field::folder, s.study.string() + " holds no study (" + study::kStudyFile + ") to resume");
  } else {
    throw StudyStartRefused(Field::definition,
                            "a new study needs its stimulus list (one tool/surface a line)");
  }

  // The participant: a taken ID (or one with nothing to resume) is refused before the folder is
  // touched.
  try {
    study::check_participant_id(s.participant);
    if (study_exists) study::check_study_settings(s);
  } catch (const std::invalid_argument& e) {
    throw StudyStartRefused(Field::participant, e.what());
  }
  if (!study_exists && s.resume)
    throw StudyStartRefused(
        Field::participant,
        "participant " + s.participant + " has no session in " + s.study.string() + " to resume");

  if (definition_.mode == study::StudyMode::rig) {
    if (!request_.rig)
      throw StudyStartRefused(Field::rig, "rig mode needs a rig to sweep the stimuli on");
    if (!request_.mount)
      throw StudyStartRefused(Field::rig,
                              "rig mode needs a way to tell the operator what to mount");
    try {
      rig_ = request_.rig();
    } catch (const std::exception& e) {
      throw StudyStartRefused(Field::rig, e.what());
    }
  }

  // Reading the catalog takes milliseconds; checking a pairing or a design point meshes nothing.
  tool_sounds_ = std::make_shared<model::design::ToolSounds>(request_.sounds);
  for (const study::Stimulus& stimulus : definition_.stimuli) {
    try {
      tool_sounds_->check(stimulus.tool, stimulus.surface);
    } catch (const std::exception& e) {
      throw StudyStartRefused(Field::stimulus, "stimulus '" + stimulus.name + "': " + e.what());
    }
  }
}

StudyStart::StudyStart(StudyStart&&) noexcept = default;
StudyStart& StudyStart::operator=(StudyStart&&) noexcept = default;
StudyStart::~StudyStart() = default;

void StudyStart::prepare(const std::function<void(std::size_t, std::size_t)>& progress) {
  const study::StudySettings& s = request_.settings;
  try {
    study::create_or_join_study(
        s.study, definition_, study_text_or_bundled(request_.instructions, "instructions.txt"),
        study_text_or_bundled(request_.consent, "consent.txt"));
  } catch (const std::invalid_argument& e) {
    throw StudyStartRefused(Field::folder, e.what());  // another study made there since the check
  }
  try {
    study::check_study_settings(s);
  } catch (const std::invalid_argument& e) {
    throw StudyStartRefused(Field::participant, e.what());
  }
  sounds_.clear();
  if (definition_.mode != study::StudyMode::rig && request_.audition) {
    for (const study::Stimulus& stimulus : definition_.stimuli) {
      sounds_.push_back(tool_sounds_->sound(stimulus.tool, stimulus.surface));
      if (progress) progress(sounds_.size(), definition_.stimuli.size());
    }
  }
  prepared_ = true;
}

ReadyStudy StudyStart::ready() {
  if (!prepared_) throw std::logic_error("StudyStart::ready() before prepare()");
  ReadyStudy ready;
  if (definition_.mode == study::StudyMode::rig) {
    // The simulated rig simulates each stimulus it is opened with; the others run what is mounted.
    const auto open = [base = *rig_, sounds = tool_sounds_](const study::Stimulus& stimulus) {
      RigRequest r = base;
      r.tool = stimulus.tool;
      r.surface = stimulus.surface;
      return open_rig(r, *sounds);
    };
    ready.presenter = std::make_unique<TurntablePresenter>(definition_.stimuli, open,
                                                           request_.mount, request_.notice);
  } else if (request_.audition) {
    ready.presenter = std::make_unique<ActuatorPresenter>(request_.audition(), std::move(sounds_));
  } else {
    ready.presenter = std::make_unique<study::NothingPresented>();
  }
  ready.session = std::make_unique<study::StudySession>(request_.settings, *ready.presenter);
  return ready;
}

ReadyStudy start_study(StudyStartRequest request,
                       const std::function<void(std::size_t, std::size_t)>& progress) {
  StudyStart start(std::move(request));
  start.prepare(progress);
  return start.ready();
}

}  // namespace nibrig::rig
