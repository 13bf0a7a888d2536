#include "tests/model/measure/gz_csv.hpp"

#include <zlib.h>

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

namespace nibrig::test {

GzColumn read_gz_csv_column(const std::filesystem::path& file, std::size_t index) {
  std::unique_ptr<gzFile_s, decltype(&gzclose)> gz(gzopen(file.c_str(), "rb"), &gzclose);
  if (!gz) throw std::runtime_error("cannot open " + file.string());
  GzColumn column;
  std::string line;
  char buffer[4096];
  bool header = true;
  std::size_t number = 0;
  auto take = [&](const std::string& row) {
    ++number;
    if (header) {
      header = false;
      return;
    }
    std::size_t start = 0;
    for (std::size_t field = 0; field < index; ++field) {
      start = row.find(',', start);
      if (start == std::string::npos) {
        ++column.short_rows;
        return;
      }
      ++start;
    }
    const std::size_t end = row.find(',', start);
    const std::string text =
        row.substr(start, end == std::string::npos ? std::string::npos : end - start);
    char* stop = nullptr;
    const double value = std::strtod(text.c_str(), &stop);
    if (text.empty() || stop == text.c_str()) {
      throw std::runtime_error(file.string() + " line " + std::to_string(number) + ": '" + text +
                               "' is not a number");
    }
    column.values.push_back(value);
  };
  while (gzgets(gz.get(), buffer, sizeof buffer) != nullptr) {
    line += buffer;
    if (!line.empty() && line.back() == '\n') {
      line.pop_back();
      if (!line.empty() && line.back() == '\r') line.pop_back();
      take(line);
      line.clear();
    }
  }
  if (!line.empty()) take(line);
  return column;
}

}  // namespace nibrig::test
