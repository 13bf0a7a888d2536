// The checks every triplet reader and the writer apply to one triplet, so that all sources reject
// the same things with the same words.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/io/triplets.hpp"

namespace nibrig::model::io {

// Whether a triplet must carry at least one response: judgments must, queries to predict need not.
enum class Responses { required, optional };

// What is wrong with `triplet` given the stimulus names: an index out of range, a stimulus used
// twice (a self-triplet), a negative count, or (when required) no response at all. nullopt when it
// is fine.
std::optional<std::string> triplet_problem(const Triplet& triplet,
                                           const std::vector<std::string>& stimuli,
                                           Responses responses = Responses::required);

// The readers with the response requirement made explicit (triplets.hpp has the public forms).
TripletSet read_triplet_csv(const std::filesystem::path& file, Responses responses);
TripletSet read_lagunas_json(const std::filesystem::path& file, Responses responses,
                             const LagunasNames& names);

class CsvHeader;
// A header with the columns of a study session's responses.csv.
bool is_response_log_header(const CsvHeader& header);

}  // namespace nibrig::model::io
