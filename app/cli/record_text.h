#pragma once
// Text of the production record's commands (history, audit, users): days, UTC times, CSV
// fields and passwords read from the terminal or standard input.
#include <cstdint>
#include <string>

namespace cutcell::cli {

// YYYY-MM-DD (UTC) as ms since the epoch; false if it is not such a day.
bool parseDay(const std::string& day, std::int64_t* ms);
// 2026-12-06T14:03:11Z; "" for 0.
std::string utcTime(std::int64_t ms);
// One CSV field: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& v);
// One line of standard input; on a terminal after `prompt` on stderr, without echo. False at
// the end of the input.
bool readSecret(const char* prompt, std::string* out);

} // namespace cutcell::cli
