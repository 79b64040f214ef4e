#include "option_checks.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace cutcell::cli {
namespace {

// Shortest text that reads back as v, in C notation ("0.1", "100", "1e+06").
std::string numberText(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::string quoted(const std::string& s) {
    return "\"" + s + "\"";
}

std::string withUnit(const std::string& text, const char* unit) {
    return *unit ? text + " " + unit : text;
}

std::string rangeText(const Range& r) {
    return withUnit("[" + numberText(r.lo) + ", " + numberText(r.hi) + "]", r.unit);
}

// The value of `name` as a number within the range, or CLI::ValidationError naming all of it.
double checkedNumber(const std::string& name, const std::string& text, const Range& r, bool whole) {
    const std::optional<double> v = parseDecimal(text);
    if (!v || (whole && *v != std::floor(*v)))
        throw CLI::ValidationError(name + " = " + quoted(text) + " is not " +
                                   (whole ? "a whole number" : "a number") + " in " + rangeText(r));
    if (!(*v >= r.lo && *v <= r.hi)) // also refuses NaN
        throw CLI::ValidationError(name + " = " + withUnit(quoted(text), r.unit) + " is outside " +
                                   rangeText(r));
    return *v;
}

// "MS" for a value in ms, "S" in s, "N" for a count.
std::string typeName(const Range& r, bool whole) {
    if (!*r.unit) return whole ? "N" : "X";
    std::string t = r.unit;
    std::transform(t.begin(), t.end(), t.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return t;
}

// Edit distance, for "did you mean".
size_t distance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
            diag = up;
        }
    }
    return row[b.size()];
}

} // namespace

std::optional<double> parseDecimal(const std::string& text) {
    double v = 0;
    const char* end = text.data() + text.size();
    const auto r = std::from_chars(text.data(), end, v);
    if (text.empty() || r.ec != std::errc() || r.ptr != end || !std::isfinite(v)) return {};
    return v;
}

bool parseNodeList(const std::string& text, std::vector<int>& out, std::string& error) {
    size_t at = 0;
    while (at <= text.size()) {
        const size_t comma = text.find(',', at);
        const std::string part =
            text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
        char* end = nullptr;
        const long a = std::strtol(part.c_str(), &end, 10);
        long b = a;
        if (*end == '-') b = std::strtol(end + 1, &end, 10);
        if (part.empty() || *end != '\0' || a < 1 || b > 127 || a > b) {
            error = quoted(part) + " is not a node id or range within 1..127";
            return false;
        }
        for (long n = a; n <= b; ++n)
            out.push_back(static_cast<int>(n));
        if (comma == std::string::npos) break;
        at = comma + 1;
    }
    return true;
}

CLI::Option* addNumber(CLI::App& cmd, const std::string& name, Range range,
                       std::function<void(double)> set, const std::string& help) {
    return cmd
        .add_option_function<std::string>(
            name,
            [name, range, set](const std::string& text) {
                set(checkedNumber(name, text, range, false));
            },
            help + "; range " + rangeText(range))
        ->type_name(typeName(range, false));
}

CLI::Option* addNumber(CLI::App& cmd, const std::string& name, double& target, Range range,
                       const std::string& help) {
    return addNumber(
        cmd, name, range, [&target](double v) { target = v; }, help);
}

CLI::Option* addNumber(CLI::App& cmd, const std::string& name, std::optional<double>& target,
                       Range range, const std::string& help) {
    return addNumber(
        cmd, name, range, [&target](double v) { target = v; }, help);
}

CLI::Option* addInteger(CLI::App& cmd, const std::string& name, std::optional<int>& target,
                        Range range, const std::string& help) {
    return cmd
        .add_option_function<std::string>(
            name,
            [name, range, &target](const std::string& text) {
                target = static_cast<int>(checkedNumber(name, text, range, true));
            },
            help + "; range " + rangeText(range))
        ->type_name(typeName(range, true));
}

CLI::Option* addChoice(CLI::App& cmd, const std::string& name,
                       const std::vector<std::string>& choices,
                       std::function<void(const std::string&)> set, const std::string& help) {
    std::string list, alternatives;
    for (const std::string& c : choices) {
        list += (list.empty() ? "" : ", ") + quoted(c);
        alternatives += (alternatives.empty() ? "" : "|") + c;
    }
    return cmd
        .add_option_function<std::string>(
            name,
            [name, choices, list, set](const std::string& text) {
                if (std::find(choices.begin(), choices.end(), text) == choices.end())
                    throw CLI::ValidationError(name + " = " + quoted(text) + " is not one of " +
                                               list);
                set(text);
            },
            help)
        ->type_name(alternatives);
}

CLI::Option* addChoice(CLI::App& cmd, const std::string& name, std::string& target,
                       const std::vector<std::string>& choices, const std::string& help) {
    return addChoice(
        cmd, name, choices, [&target](const std::string& v) { target = v; }, help);
}

CLI::Option* addNodeList(CLI::App& cmd, const std::string& name, std::string& text,
                         std::vector<int>& nodes, const std::string& help) {
    return cmd
        .add_option_function<std::string>(
            name,
            [name, &text, &nodes](const std::string& value) {
                std::vector<int> ids;
                std::string error;
                if (!parseNodeList(value, ids, error))
                    throw CLI::ValidationError(name + " = " + quoted(value) + ": " + error);
                text = value;
                nodes = ids;
            },
            help)
        ->type_name("LIST");
}

CLI::Option* addHex16(CLI::App& cmd, const std::string& name, std::optional<std::uint16_t>& target,
                      const std::string& what, const std::string& help) {
    return cmd
        .add_option_function<std::string>(
            name,
            [name, what, &target](const std::string& text) {
                // strtoul: integers have no locale-dependent notation.
                char* end = nullptr;
                const unsigned long c = std::strtoul(text.c_str(), &end, 0);
                if (text.empty() || text[0] == '-' || *end != '\0' || c == 0 || c > 0xFFFF)
                    throw CLI::ValidationError(name + " = " + quoted(text) + " is not " + what +
                                               " in 0x0001..0xFFFF");
                target = static_cast<std::uint16_t>(c);
            },
            help)
        ->type_name("0xNNNN");
}

std::string unexpectedArguments(const CLI::App& cmd, const std::vector<std::string>& extras) {
    std::string msg;
    for (const std::string& arg : extras) {
        if (!msg.empty()) msg += "; ";
        if (arg.rfind('-', 0) != 0) {
            msg += "unexpected argument " + quoted(arg);
            continue;
        }
        msg += "unknown option " + arg.substr(0, arg.find('='));
        // The nearest option of this command, if the name looks like a slip of the fingers.
        const std::string given = arg.substr(0, arg.find('='));
        std::string best;
        size_t bestDistance = std::string::npos;
        for (const CLI::Option* opt : cmd.get_options()) {
            for (const std::string& lname : opt->get_lnames()) {
                const std::string candidate = "--" + lname;
                const size_t d = distance(given, candidate);
                if (d < bestDistance) {
                    bestDistance = d;
                    best = candidate;
                }
            }
        }
        if (!best.empty() && bestDistance <= std::max<size_t>(2, given.size() / 4))
            msg += " (did you mean " + best + "?)";
    }
    return msg;
}

} // namespace cutcell::cli
