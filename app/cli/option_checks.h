#pragma once
// CLI11 options of cutcell-cli whose values are checked while parsing: numbers with a unit and
// a range, choices, node lists, EMCY codes. A bad value throws CLI::ValidationError with a
// message that names the option, the value, the unit and the limit, e.g.
//   --period-ms = "0.01" ms is outside [0.1, 100] ms
// Numbers are read as written in C ("2.5"), whatever the process locale (de_DE: "2,5").
#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cutcell::cli {

// A decimal number in C notation; nothing for anything else (text after it, "2,5", empty).
std::optional<double> parseDecimal(const std::string& text);

// "1-6", "1,3,5" or "2-3,7": node ids 1..127 appended to out; false with the bad part otherwise.
bool parseNodeList(const std::string& text, std::vector<int>& out, std::string& error);

struct Range {
    double lo, hi;
    const char* unit; // "ms", "s", "" (a count)
};

// --name VALUE within the range, handed to `set` (which may convert the unit).
CLI::Option* addNumber(CLI::App& cmd, const std::string& name, Range range,
                       std::function<void(double)> set, const std::string& help);
CLI::Option* addNumber(CLI::App& cmd, const std::string& name, double& target, Range range,
                       const std::string& help);
CLI::Option* addNumber(CLI::App& cmd, const std::string& name, std::optional<double>& target,
                       Range range, const std::string& help);
// A whole number within [range.lo, range.hi].
CLI::Option* addInteger(CLI::App& cmd, const std::string& name, std::optional<int>& target,
                        Range range, const std::string& help);
// One of `choices`, e.g. --clock realtime|fast.
CLI::Option* addChoice(CLI::App& cmd, const std::string& name,
                       const std::vector<std::string>& choices,
                       std::function<void(const std::string&)> set, const std::string& help);
CLI::Option* addChoice(CLI::App& cmd, const std::string& name, std::string& target,
                       const std::vector<std::string>& choices, const std::string& help);
// --nodes LIST: fills the list as given and expanded.
CLI::Option* addNodeList(CLI::App& cmd, const std::string& name, std::string& text,
                         std::vector<int>& nodes, const std::string& help);
// A 16-bit code or object index 0x0001..0xFFFF (hex with 0x, or decimal); `what` names it in
// the refusal ("an EMCY code").
CLI::Option* addHex16(CLI::App& cmd, const std::string& name, std::optional<std::uint16_t>& target,
                      const std::string& what, const std::string& help);

// "unknown option --reprot (did you mean --report?)" for the arguments `cmd` did not expect.
std::string unexpectedArguments(const CLI::App& cmd, const std::vector<std::string>& extras);

} // namespace cutcell::cli
