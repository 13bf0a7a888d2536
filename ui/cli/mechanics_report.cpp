#include "ui/cli/mechanics_report.hpp"

#include <cctype>

namespace nibrig::ui::cli {

std::string file_stem(const std::string& name) {
  std::string stem;
  for (char c : name) stem += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return stem;
}

}  // namespace nibrig::ui::cli
