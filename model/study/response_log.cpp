#include "model/study/response_log.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/text_lines.hpp"
#include "model/io/utc_time.hpp"
#include "model/io/finite_output.hpp"

namespace nibrig::model::study {
namespace {

namespace jf = io::json_fields;

constexpr const char* kParticipantFormat = "nibrig-participant";
constexpr long long kParticipantVersion = 1;
constexpr const char* kResponsesHeader =
    "trial,practice,stage,reference,left,right,chosen,response_s,plays,answered_utc";
constexpr std::size_t kResponseFields = 10;

[[noreturn]] void fail_on_system(const std::filesystem::path& file, const std::string& what) {
  throw std::runtime_error(file.string() + ": cannot " + what + ": " + std::strerror(errno));
}

void write_all(int fd, const std::string& text, const std::filesystem::path& file) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail_on_system(file, "append a response");
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

void check_participant_id(const std::string& id) {
  bool ok = !id.empty() && id.size() <= 64 && id.front() != '.';
  for (char c : id)
    ok = ok && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                c == '-' || c == '_' || c == '.');
  if (!ok)
    throw std::invalid_argument("participant ID '" + id +
                                "': expected 1-64 letters, digits, '-', '_' or '.', not starting "
                                "with '.' (it names a folder)");
}

std::uint64_t seed_of_participant(const std::string& id) {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a: stable across runs and compilers
  for (unsigned char c : id) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

void write_participant_file(const std::filesystem::path& file, const ParticipantRecord& r) {
  const nlohmann::json j = {{"format", kParticipantFormat}, {"version", kParticipantVersion},
                            {"id", r.id},                   {"seed", std::to_string(r.seed)},
                            {"respondent", r.respondent},   {"created_utc", r.created_utc}};
  io::write_file_atomically(file, io::json_text(j, file));
}

ParticipantRecord read_participant_file(const std::filesystem::path& file) {
  const nlohmann::json j = jf::parse_file(file);
  jf::as_object(j, file, "");
  jf::check_format_and_version(j, file, kParticipantFormat, kParticipantVersion);
  ParticipantRecord r;
  r.id = jf::string_member(j, "id", file, "");
  // A decimal string: a 64-bit seed does not survive JSON readers that hold numbers as doubles.
  const std::string seed = jf::string_member(j, "seed", file, "");
  std::size_t used = 0;
  try {
    r.seed = std::stoull(seed, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != seed.size() || seed.front() == '-')
    throw io::FormatError(file, jf::place("seed"),
                          "expected a whole number 0-2^64-1 as text, found " + io::in_quotes(seed));
  r.respondent = jf::string_member(j, "respondent", file, "");
  r.created_utc = jf::string_member(j, "created_utc", file, "");
  return r;
}

ResponseLog::ResponseLog(std::filesystem::path file, std::vector<std::string> stimuli)
    : file_(std::move(file)), stimuli_(std::move(stimuli)) {
  fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) fail_on_system(file_, "open for appending");
  const off_t size = ::lseek(fd_, 0, SEEK_END);
  if (size < 0) fail_on_system(file_, "find the end");
  if (size == 0) {
    write_all(fd_, std::string(kResponsesHeader) + "\n", file_);
  } else {
    // Find the end of the last complete line: what follows it was cut off mid-write.
    off_t keep = size;
    char c = 0;
    while (keep > 0) {
      if (::pread(fd_, &c, 1, keep - 1) != 1) fail_on_system(file_, "read back");
      if (c == '\n') break;
      --keep;
    }
    if (keep < size) {
      if (::ftruncate(fd_, keep) != 0) fail_on_system(file_, "remove a cut-off last line");
      removed_cut_off_ = true;
    }
    if (keep == 0) write_all(fd_, std::string(kResponsesHeader) + "\n", file_);
  }
  if (::fsync(fd_) != 0) fail_on_system(file_, "flush to disk");
}

ResponseLog::~ResponseLog() {
  if (fd_ >= 0) ::close(fd_);
}

void ResponseLog::append(const LoggedResponse& r) {
  auto name = [this](std::size_t index) { return stimuli_.at(index); };
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.3f", r.response_s);
  const std::string line =
      std::to_string(r.trial) + "," + (r.practice ? "1" : "0") + "," +
      std::to_string(r.planned.stage) + "," + name(r.planned.reference) + "," +
      name(r.planned.left) + "," + name(r.planned.right) + "," +
      (r.chosen == space::Choice::left ? "left" : "right") + "," + seconds + "," + r.plays + "," +
      r.answered_utc + "\n";
  write_all(fd_, line, file_);
  if (::fdatasync(fd_) != 0) fail_on_system(file_, "flush a response to disk");
}

ResponseFile read_response_file(const std::filesystem::path& file,
                                const std::vector<std::string>& stimuli, int last_stage) {
  std::map<std::string, std::size_t> index_of;
  for (std::size_t i = 0; i < stimuli.size(); ++i) index_of[stimuli[i]] = i;
  io::CsvReader reader(file, kResponsesHeader);
  const io::CsvHeader& h = reader.header();
  const std::size_t c_trial = h.column("trial"), c_practice = h.column("practice"),
                    c_stage = h.column("stage"), c_reference = h.column("reference"),
                    c_left = h.column("left"), c_right = h.column("right"),
                    c_chosen = h.column("chosen"), c_time = h.column("response_s"),
                    c_plays = h.column("plays"), c_utc = h.column("answered_utc");
  ResponseFile out;
  std::vector<std::string_view> f;
  while (reader.next(f)) {
    // A crash mid-write leaves a line without its ending (and maybe without all its fields).
    if (reader.row_unterminated()) {
      out.warnings.push_back(file.string() + " line " + std::to_string(reader.line_number()) +
                             " is cut off (no line ending) and was dropped");
      break;
    }
    reader.require_fields(f, kResponseFields);
    const std::size_t line = reader.line_number();
    LoggedResponse r;
    const long long trial = io::parse_integer(f[c_trial], file, line, "trial");
    if (trial != static_cast<long long>(out.responses.size()) + 1)
      throw io::FormatError(file, io::field_place(line, "trial"),
                            "expected trial " + std::to_string(out.responses.size() + 1) +
                                " (trials are numbered in order from 1), found " +
                                io::in_quotes(f[c_trial]));
    r.trial = static_cast<std::size_t>(trial);
    if (f[c_practice] != "0" && f[c_practice] != "1")
      throw io::FormatError(file, io::field_place(line, "practice"),
                            "expected 0 or 1, found " + io::in_quotes(f[c_practice]));
    r.practice = f[c_practice] == "1";
    const long long stage = io::parse_integer(f[c_stage], file, line, "stage");
    if (stage < 1 || stage > last_stage)
      throw io::FormatError(file, io::field_place(line, "stage"),
                            "expected a stage from 1 to " + std::to_string(last_stage) +
                                " (the study's plan has no other), found " +
                                io::in_quotes(f[c_stage]));
    r.planned.stage = static_cast<int>(stage);
    auto stimulus = [&](std::size_t column, const char* field) {
      const auto it = index_of.find(std::string(f[column]));
      if (it == index_of.end())
        throw io::FormatError(file, io::field_place(line, field),
                              "stimulus " + io::in_quotes(f[column]) + " is not in the study");
      return it->second;
    };
    r.planned.reference = stimulus(c_reference, "reference");
    r.planned.left = stimulus(c_left, "left");
    r.planned.right = stimulus(c_right, "right");
    if (f[c_chosen] == "left")
      r.chosen = space::Choice::left;
    else if (f[c_chosen] == "right")
      r.chosen = space::Choice::right;
    else
      throw io::FormatError(file, io::field_place(line, "chosen"),
                            "expected left or right, found " + io::in_quotes(f[c_chosen]));
    r.response_s = io::parse_number(f[c_time], file, line, "response_s");
    // A day: a trial left open over a break is still an answer; 1e308 s is not.
    if (r.response_s < 0 || r.response_s > 86400)
      throw io::FormatError(file, io::field_place(line, "response_s"),
                            "expected a time from 0 to 86400 s (a day), found " + io::in_quotes(f[c_time]));
    r.plays = std::string(f[c_plays]);
    if (r.plays.find_first_not_of("RAB") != std::string::npos)
      throw io::FormatError(file, io::field_place(line, "plays"),
                            "expected the letters R, A and B (reference, left, right), found " +
                                io::in_quotes(f[c_plays]));
    if (!io::is_utc_iso8601(f[c_utc]))
      throw io::FormatError(file, io::field_place(line, "answered_utc"),
                            "expected a UTC time like 2026-11-26T04:01:02Z, found " +
                                io::in_quotes(f[c_utc]));
    r.answered_utc = std::string(f[c_utc]);
    out.responses.push_back(std::move(r));
  }
  return out;
}

}  // namespace nibrig::model::study
