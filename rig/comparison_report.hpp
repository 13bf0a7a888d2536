// The live comparison's table as the report file's content (model/io/comparison_file.hpp,
// comparison.json): what `nibrig rig compare --report DIR` writes when the turntable stops.
#pragma once

#include <string>

#include "model/io/comparison_file.hpp"
#include "rig/live_comparison.hpp"

namespace nibrig::rig {

model::io::ComparisonFile comparison_report(const std::string& tool, const std::string& surface,
                                            const ComparisonTable& table,
                                            const LiveComparisonSettings& settings);

}  // namespace nibrig::rig
