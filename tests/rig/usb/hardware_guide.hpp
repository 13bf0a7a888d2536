// rig/HARDWARE.md as the tests read it: its failure-modes table (each fault's bound and the test that
// shows it) and its table of figures the firmware or the board model determine. The tests take their
// bounds and expected figures from here, so that the guide cannot drift from the code again.
#pragma once

#include <string>
#include <vector>

namespace nibrig::rig::usb::testing {

struct GuideFailureMode {
  std::string fault;   // the first column, e.g. "encoder A and B swapped"
  std::string within;  // as written, e.g. "100 ms (measured 29–52)"
  std::string test;    // "Suite.Name" (a parameterised test's suite and name, without its instance)
};

struct GuideFigure {
  std::string figure;
  std::string value;  // as written: its first number is the figure
  std::string test;
};

std::vector<GuideFailureMode> hardware_guide_failure_modes();
std::vector<GuideFigure> hardware_guide_figures();
// The first number of a row's "within" cell, in ms; throws naming the fault when there is no such
// row or no number.
double hardware_guide_within_ms(const std::string& fault);
// The first number of a figure's value; throws naming the figure when absent.
double hardware_guide_figure(const std::string& figure);

}  // namespace nibrig::rig::usb::testing
