#include "rig/study/study_rehearsal.hpp"

#include <fmt/format.h>

#include "model/design/design_search.hpp"
#include "model/space/space_file.hpp"
#include "model/study/response_log.hpp"

namespace nibrig::rig {

namespace study = model::study;

Rehearsal rehearse_from(StudyStart& start, const std::filesystem::path& space_file, double lapse_rate,
                        std::optional<std::uint64_t> seed) {
  const model::space::SpaceFile space = model::space::read_space_file(space_file);
  const study::StudyDefinition& definition = start.definition();
  model::design::ToolSounds& sounds = start.tool_sounds();
  const study::PlaceOther predicted = [&](const study::Stimulus& s) -> std::optional<Eigen::VectorXd> {
    if (!model::design::names_design_point(s.tool) || !space.descriptor_map) return std::nullopt;
    return model::design::place_predicted(*space.descriptor_map, sounds.predict(s.tool, s.surface)).mean;
  };
  Rehearsal r;
  r.truth = study::truth_for_stimuli(space, space_file, definition.stimuli, start.catalog_file(),
                                     predicted);
  r.judging = study::judgment_model_for_stimuli(space, definition.stimuli);
  study::SimulatedParticipantOptions options;
  options.lapse_rate = lapse_rate;
  const study::StudySettings& settings = start.settings();
  std::uint64_t chosen = seed.value_or(study::seed_of_participant(settings.participant));
  const auto record = study::participant_folder(settings.study, settings.participant) / study::kParticipantFile;
  if (settings.resume && !seed && std::filesystem::exists(record))
    chosen = study::read_participant_file(record).seed;
  r.participant = std::make_unique<study::SimulatedParticipant>(r.truth, options, chosen, r.judging);
  start.record_respondent("simulated from " + space_file.string() +
                          fmt::format(" (judging by {}, lapse rate {} besides)",
                                      model::space::family_name(r.judging.family), lapse_rate));
  return r;
}

}  // namespace nibrig::rig
