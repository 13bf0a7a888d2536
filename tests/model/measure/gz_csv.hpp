// Test-only reader of the paper's gzip CSV recordings, so that the measure tests do not depend on
// the model/io readers being written at the same time. It returns one numeric column and says what
// it skipped.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

namespace nibrig::test {

struct GzColumn {
  std::vector<double> values;
  std::size_t short_rows =
      0;  // rows with fewer fields than the column index (e.g. a truncated last line)
};

// Reads column `index` (0-based) of every data row after the header line. Throws std::runtime_error
// when the file cannot be opened or a field of that column is not a number.
GzColumn read_gz_csv_column(const std::filesystem::path& file, std::size_t index);

}  // namespace nibrig::test
