#include "tests/rig/usb/hardware_guide.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace nibrig::rig::usb::testing {
namespace {

const char* const kHardwareGuide = NIBRIG_SOURCE_DIR "/rig/HARDWARE.md";

std::string guide_trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// The rows of the first table after the heading `heading`, as cells; the header and its rule are
// skipped.
std::vector<std::vector<std::string>> guide_table(const std::string& heading) {
  std::ifstream in(kHardwareGuide);
  if (!in) throw std::runtime_error(std::string("cannot read ") + kHardwareGuide);
  std::string line;
  bool found = false;
  while (std::getline(in, line)) {
    if (line == heading) {
      found = true;
      break;
    }
  }
  if (!found) throw std::runtime_error(std::string(kHardwareGuide) + " has no heading '" + heading + "'");
  std::vector<std::vector<std::string>> rows;
  bool in_table = false;
  int header_lines = 0;
  while (std::getline(in, line)) {
    if (line.rfind("|", 0) != 0) {
      if (in_table) break;
      continue;
    }
    in_table = true;
    if (header_lines < 2) {
      ++header_lines;
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream row(line.substr(1));
    std::string cell;
    while (std::getline(row, cell, '|')) cells.push_back(guide_trim(cell));
    rows.push_back(cells);
  }
  return rows;
}

double guide_first_number(const std::string& text, const std::string& what) {
  const auto at = text.find_first_of("0123456789");
  if (at == std::string::npos) throw std::runtime_error(std::string(kHardwareGuide) + ": " + what + " has no number: " + text);
  return std::stod(text.substr(at));
}

// A test's name as the guide writes it, in back quotes.
std::string guide_unquote(const std::string& cell) {
  const auto open = cell.find('`'), close = cell.rfind('`');
  return open != std::string::npos && close > open ? cell.substr(open + 1, close - open - 1) : cell;
}

}  // namespace

std::vector<GuideFailureMode> hardware_guide_failure_modes() {
  std::vector<GuideFailureMode> modes;
  for (const auto& cells : guide_table("## Failure modes")) {
    if (cells.size() < 6) throw std::runtime_error(std::string(kHardwareGuide) + ": a failure-mode row has too few cells");
    modes.push_back({cells[0], cells[2], guide_unquote(cells[5])});
  }
  return modes;
}

std::vector<GuideFigure> hardware_guide_figures() {
  std::vector<GuideFigure> figures;
  for (const auto& cells : guide_table("### Figures the tests hold")) {
    if (cells.size() < 3) throw std::runtime_error(std::string(kHardwareGuide) + ": a figure row has too few cells");
    figures.push_back({cells[0], cells[1], guide_unquote(cells[2])});
  }
  return figures;
}

double hardware_guide_within_ms(const std::string& fault) {
  for (const GuideFailureMode& m : hardware_guide_failure_modes()) {
    if (m.fault == fault) return guide_first_number(m.within, "the bound of '" + fault + "'");
  }
  throw std::runtime_error(std::string(kHardwareGuide) + " has no failure mode '" + fault + "'");
}

double hardware_guide_figure(const std::string& figure) {
  for (const GuideFigure& f : hardware_guide_figures()) {
    if (f.figure == figure) return guide_first_number(f.value, "the figure '" + figure + "'");
  }
  throw std::runtime_error(std::string(kHardwareGuide) + " has no figure '" + figure + "'");
}

}  // namespace nibrig::rig::usb::testing
