#include "model/space/query_csv.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/quoted_csv.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::space {

std::string embed_csv_text(const std::vector<PlacedPairing>& placed, std::size_t dims) {
  std::ostringstream csv;
  csv << "stimulus,judged";
  for (std::size_t d = 0; d < dims; ++d) csv << ",axis" << d + 1 << ",axis" << d + 1 << "_sd";
  csv << '\n' << std::setprecision(8);
  for (const PlacedPairing& p : placed) {
    if (static_cast<std::size_t>(p.placement.mean.size()) != dims)
      throw std::invalid_argument("placement of " + p.pairing + " has " +
                                  std::to_string(p.placement.mean.size()) + " axes, expected " +
                                  std::to_string(dims));
    csv << io::csv_field(p.pairing) << ',' << (p.judged ? "yes" : "no");
    for (std::size_t d = 0; d < dims; ++d) {
      const auto k = static_cast<Eigen::Index>(d);
      csv << ',' << p.placement.mean(k) << ',' << std::sqrt(p.placement.covariance(k, k));
    }
    csv << '\n';
  }
  return csv.str();
}

void write_embed_csv(const std::filesystem::path& file, const std::vector<PlacedPairing>& placed,
                     std::size_t dims) {
  io::write_file_atomically(file, embed_csv_text(placed, dims));
}

std::vector<EmbedRow> read_embed_csv(const std::filesystem::path& file) {
  const io::QuotedCsv table = io::read_quoted_csv(file);
  const std::size_t columns = table.header.size();
  bool header_ok = columns >= 4 && columns % 2 == 0 && table.header[0] == "stimulus" &&
                   table.header[1] == "judged";
  for (std::size_t d = 0; header_ok && 2 + 2 * d < columns; ++d)
    header_ok = table.header[2 + 2 * d] == "axis" + std::to_string(d + 1) &&
                table.header[3 + 2 * d] == "axis" + std::to_string(d + 1) + "_sd";
  if (!header_ok)
    throw io::FormatError(file, io::line_place(1),
                          "expected the header 'stimulus,judged,axis1,axis1_sd,...'");
  const auto dims = static_cast<Eigen::Index>((columns - 2) / 2);
  std::vector<EmbedRow> rows;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto& f = table.rows[r];
    const std::size_t line = table.line_numbers[r];
    EmbedRow row;
    row.stimulus = f[0];
    if (f[1] != "yes" && f[1] != "no")
      throw io::FormatError(file, io::field_place(line, "judged"),
                            "expected yes or no, found " + io::in_quotes(f[1]));
    row.judged = f[1] == "yes";
    row.mean.resize(dims);
    row.sd.resize(dims);
    for (Eigen::Index d = 0; d < dims; ++d) {
      const auto c = static_cast<std::size_t>(2 + 2 * d);
      row.mean(d) = io::parse_number(f[c], file, line, table.header[c]);
      row.sd(d) = io::parse_number(f[c + 1], file, line, table.header[c + 1]);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string prediction_csv_text(const io::TripletSet& queries,
                                const std::vector<QueryPrediction>& predictions, bool with_sd) {
  if (predictions.size() != queries.triplets.size())
    throw std::invalid_argument("expected one prediction per query triplet (" +
                                std::to_string(queries.triplets.size()) + "), found " +
                                std::to_string(predictions.size()));
  std::ostringstream csv;
  csv << "reference,a,b,p_first" << (with_sd ? ",p_first_sd" : "") << '\n'
      << std::setprecision(10);
  for (std::size_t i = 0; i < predictions.size(); ++i) {
    const auto& t = queries.triplets[i];
    csv << io::csv_field(queries.stimuli[t.reference]) << ','
        << io::csv_field(queries.stimuli[t.a]) << ',' << io::csv_field(queries.stimuli[t.b])
        << ',' << predictions[i].p;
    if (with_sd) csv << ',' << predictions[i].sd;
    csv << '\n';
  }
  return csv.str();
}

void write_prediction_csv(const std::filesystem::path& file, const io::TripletSet& queries,
                          const std::vector<QueryPrediction>& predictions, bool with_sd) {
  io::write_file_atomically(file, prediction_csv_text(queries, predictions, with_sd));
}

std::vector<PredictionRow> read_prediction_csv(const std::filesystem::path& file) {
  const io::QuotedCsv table = io::read_quoted_csv(file);
  const std::vector<std::string> plain{"reference", "a", "b", "p_first"};
  std::vector<std::string> with_sd = plain;
  with_sd.push_back("p_first_sd");
  if (table.header != plain && table.header != with_sd)
    throw io::FormatError(file, io::line_place(1),
                          "expected the header 'reference,a,b,p_first[,p_first_sd]'");
  const bool sd = table.header.size() == 5;
  std::vector<PredictionRow> rows;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto& f = table.rows[r];
    const std::size_t line = table.line_numbers[r];
    PredictionRow row{f[0], f[1], f[2], io::parse_number(f[3], file, line, "p_first"), {}};
    if (sd) row.p_first_sd = io::parse_number(f[4], file, line, "p_first_sd");
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace nibrig::model::space
