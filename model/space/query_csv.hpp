// The CSV tables a fitted space answers with (FORMATS.md, "Perceptual space"): the embed table,
// every catalog pairing placed from its descriptors, and the predict table, P(first) per queried
// triplet. Names holding a comma, a quote or a line break are quoted (model/io/quoted_csv.hpp).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/io/triplets.hpp"
#include "model/space/space_inputs.hpp"
#include "model/space/space_tools.hpp"

namespace nibrig::model::space {

// `stimulus,judged,axis1,axis1_sd,…` with `dims` axes: a placement's mean and the square root of
// its covariance's diagonal, eight significant digits; judged `yes` or `no`.
std::string embed_csv_text(const std::vector<PlacedPairing>& placed, std::size_t dims);
// Throws as io::write_file_atomically.
void write_embed_csv(const std::filesystem::path& file, const std::vector<PlacedPairing>& placed,
                     std::size_t dims);

struct EmbedRow {
  std::string stimulus;
  bool judged = false;
  Eigen::VectorXd mean, sd;  // one value per axis
};
// Throws io::FormatError naming the file, line and field: a header that is not the embed table's,
// a field that is not a number, judged other than yes or no, an unterminated quote.
std::vector<EmbedRow> read_embed_csv(const std::filesystem::path& file);

// `reference,a,b,p_first[,p_first_sd]`, one row per query triplet of `queries`, ten significant
// digits; p_first_sd when `with_sd` (the queries placed from descriptors carry an uncertainty).
std::string prediction_csv_text(const io::TripletSet& queries,
                                const std::vector<QueryPrediction>& predictions, bool with_sd);
void write_prediction_csv(const std::filesystem::path& file, const io::TripletSet& queries,
                          const std::vector<QueryPrediction>& predictions, bool with_sd);

struct PredictionRow {
  std::string reference, a, b;
  double p_first = 0.0;
  std::optional<double> p_first_sd;
};
// Throws io::FormatError as read_embed_csv does.
std::vector<PredictionRow> read_prediction_csv(const std::filesystem::path& file);

}  // namespace nibrig::model::space
