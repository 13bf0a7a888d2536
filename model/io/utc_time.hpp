// The time stamps our files carry (a session's creation, a calibration's, each answer of a study):
// UTC as ISO 8601 to the second, one spelling everywhere.
#pragma once

#include <string>

namespace nibrig::model::io {

// Now, as "2026-11-26T04:01:02Z".
std::string now_utc_iso8601();

}  // namespace nibrig::model::io
