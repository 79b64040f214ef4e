// cutcell-cli fk / ik: forward and inverse kinematics of an arm machine's arm, as JSON,
// through MachineModule::forwardKinematics / inverseKinematics (other machines: exit 64 with
// "... is not an arm machine"). A pose without any solution (Outcome Incomplete): the JSON with
// its reason, exit 3.
#include "cli_commands.h"

#include "core/json/json.h"
#include "core/machine/machine_registry.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace cutcell::cli {
namespace {

bool parseList(const std::string& text, const char* option, std::vector<double>& out) {
    size_t i = 0;
    while (i <= text.size()) {
        const size_t j = std::min(text.find(',', i), text.size());
        double v = 0;
        const auto r = std::from_chars(text.data() + i, text.data() + j, v);
        if (r.ec != std::errc() || r.ptr != text.data() + j || !std::isfinite(v)) {
            std::fprintf(stderr, "%s: %s is not a list of numbers (value %zu: \"%s\")\n", option,
                         json::quote(text).c_str(), out.size() + 1, text.substr(i, j - i).c_str());
            return false;
        }
        out.push_back(v);
        i = j + 1;
    }
    return true;
}

int run(const KinematicsOptions& o, bool forward) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
    std::vector<double> values;
    if (!parseList(o.values, forward ? "--joints" : "--pose", values)) return kUsage;
    const MachineModule& m = machineFor(job);
    json::Value out;
    const Outcome done = forward ? m.forwardKinematics(job, o.arm, values, &out)
                                 : m.inverseKinematics(job, o.arm, values, &out);
    if (done.status == OutcomeStatus::Incomplete) {
        // Answered, but no solution (a pose out of reach): the JSON says why; exit 3 as an
        // unreachable plan does.
        std::fputs(json::write(out).c_str(), stdout);
        std::fputs("\n", stdout);
        std::fprintf(stderr, "%s\n", done.message.c_str());
        return kUnreachable;
    }
    if (!done.ok()) {
        std::fprintf(stderr, "%s\n", done.message.c_str());
        return kUsage;
    }
    std::fputs(json::write(out).c_str(), stdout);
    std::fputs("\n", stdout);
    return kOk;
}

} // namespace

int runFk(const KinematicsOptions& o) {
    return run(o, true);
}
int runIk(const KinematicsOptions& o) {
    return run(o, false);
}

} // namespace cutcell::cli
