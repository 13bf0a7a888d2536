// What one part of `nibrig demo` reports: its lines for SUMMARY.txt, for a person, and its numbers
// for SUMMARY.json, for a script or a test, which check figures rather than prose.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace nibrig::ui::cli {

struct DemoSection {
  std::string text;
  nlohmann::json numbers = nlohmann::json::object();
};

}  // namespace nibrig::ui::cli
