// A study rehearsed before anyone comes in: a simulated participant answers every trial from a
// perceptual space, judging by that space's model, so that an experimenter sees the whole session
// (plan, rests, files, report) as a person would leave it. The same for every face: `experiment run
// --simulate` and the panel's rehearsal.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>

#include "model/space/simulated_observer.hpp"
#include "model/study/simulated_participant.hpp"
#include "rig/study/study_start.hpp"

namespace nibrig::rig {

struct Rehearsal {
  Eigen::MatrixXd truth;                // dims × the study's stimuli, where the space puts them
  model::space::JudgmentModel judging;  // the space's model for these stimuli
  std::unique_ptr<model::study::SimulatedParticipant> participant;
};

// The simulated participant of `start`'s study, answering from `space_file`: judged stimuli at the
// space's coordinates, other catalog pairings through its map, design points placed from their
// predicted descriptors (seconds each: the FEM, so call it off a UI thread). Its seed is `seed`,
// else a resumed participant's recorded one, else the participant ID's, so that a resumed rehearsal
// answers as an uninterrupted one. Records the respondent in `start`. Throws what the space reader
// and truth_for_stimuli throw (naming the space file), std::invalid_argument for a lapse rate
// outside [0, 1].
Rehearsal rehearse_from(StudyStart& start, const std::filesystem::path& space_file, double lapse_rate,
                        std::optional<std::uint64_t> seed = std::nullopt);

}  // namespace nibrig::rig
