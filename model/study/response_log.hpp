// What a participant has answered, on disk the moment it is answered: one line per trial appended
// to `responses.csv` and flushed to the disk before the next trial starts, so that a crash, a
// kill -9 or a power cut loses at most the trial in progress. `participant.json` beside it holds
// who answered and the seed of their trial order, which a resumed session must reuse.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "model/space/trial_plan.hpp"

namespace nibrig::model::study {

// The order in which the participant asked for the three stimuli of a trial: R (reference),
// A (left), B (right), e.g. "RARBAB".
struct LoggedResponse {
  std::size_t trial = 0;  // 1-based, practice included
  bool practice = false;
  space::Trial planned;   // indices into the study's stimuli
  space::Choice chosen = space::Choice::none;
  double response_s = 0.0;  // from the trial's start to the answer
  std::string plays;
  std::string answered_utc;  // ISO 8601
};

inline constexpr const char* kResponsesFile = "responses.csv";
inline constexpr const char* kParticipantFile = "participant.json";
inline constexpr const char* kParticipantsFolder = "participants";

// A participant ID names a folder: 1-64 letters, digits, '-', '_' or '.', not starting with '.'.
// Throws std::invalid_argument saying so.
void check_participant_id(const std::string& id);

struct ParticipantRecord {
  std::string id;
  std::uint64_t seed = 0;
  std::string respondent;   // "a person", or the simulated observer's description
  std::string created_utc;  // ISO 8601
};

// The seed a participant's order is drawn with when none is given: a hash of the ID, so that
// participants meet different orders and one ID always the same.
std::uint64_t seed_of_participant(const std::string& id);

void write_participant_file(const std::filesystem::path& file, const ParticipantRecord& record);
// Throws io::FormatError naming the file and field.
ParticipantRecord read_participant_file(const std::filesystem::path& file);

// Appends to a responses file (made with its header when it does not exist yet). A line cut off
// by a crash at the end of the file is removed first, so the next line starts on a line of its
// own. Throws std::runtime_error naming the file and the system's reason when it cannot be opened
// or written.
class ResponseLog {
 public:
  ResponseLog(std::filesystem::path file, std::vector<std::string> stimuli);
  ~ResponseLog();
  ResponseLog(const ResponseLog&) = delete;
  ResponseLog& operator=(const ResponseLog&) = delete;

  // Written and flushed to the disk (fsync) before it returns.
  void append(const LoggedResponse& response);
  // True when opening removed a cut-off last line.
  bool removed_cut_off_line() const noexcept { return removed_cut_off_; }

 private:
  std::filesystem::path file_;
  std::vector<std::string> stimuli_;
  int fd_ = -1;
  bool removed_cut_off_ = false;
};

struct ResponseFile {
  std::vector<LoggedResponse> responses;
  std::vector<std::string> warnings;  // a cut-off last line, dropped
};

// Reads a responses file of a study with these stimuli. Throws io::FormatError naming the file,
// line and field: an unknown stimulus name, a trial number out of sequence, chosen other than
// left/right, a negative response time, plays with letters other than R, A, B, a stage outside
// [1, last_stage] (trial_sequence.hpp's last_stage), a time stamp now_utc_iso8601 would not write.
ResponseFile read_response_file(const std::filesystem::path& file,
                                const std::vector<std::string>& stimuli, int last_stage);

}  // namespace nibrig::model::study
