// Tables of values at the tip and material curves' knots, in dB, as `forcing fit` and `forcing
// holdout` print them: a header of knot frequencies, then per quantity a row of values with,
// under it, a row of their standard errors.
#pragma once

#include <string>
#include <vector>

namespace nibrig::ui::cli {

// `label` left-aligned in `label_width` columns, then each knot frequency (Hz).
std::string knot_table_header(const std::string& label, const std::vector<double>& knots_hz,
                              int label_width);

// Natural-log gains printed in dB; the "± (SE)" row only when standard errors are given.
std::string knot_table_rows(const std::string& label, const std::vector<double>& log_gains,
                            const std::vector<double>& standard_errors, int label_width);

}  // namespace nibrig::ui::cli
