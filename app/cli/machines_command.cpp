// cutcell-cli machines: every registered machine (id, title, axes, exports), and
// cutcell-cli upgrade: a schema-1 job file rewritten as schema 2 (core/job/job_io.h).
#include "cli_commands.h"

#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/machine_registry.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace cutcell::cli {
namespace {

// Axis limits of a machine's default job; |limit| >= this is an axis without a stop.
constexpr double kNoStop = 1e9;

json::Value machineJson(const MachineModule& m) {
    const Job job = m.defaultJob();
    json::Array axes;
    for (const AxisInfo& a : m.axes(job))
        axes.push_back(json::Object{{"name", a.name},
                                    {"unit", unitSymbol(a.unit)},
                                    {"min", a.min},
                                    {"max", a.max},
                                    {"command_mode", commandModeName(a.mode)}});
    json::Array exports;
    for (const ExportInfo& e : m.exports())
        exports.push_back(json::Object{{"id", e.id},
                                       {"title", e.title},
                                       {"default_name", e.default_name},
                                       {"plan_file", e.plan_file},
                                       {"binary", e.binary}});
    return json::Object{{"id", m.id()},
                        {"title", m.title()},
                        {"canopen", m.canOpen().ok()},
                        {"axes", axes},
                        {"exports", exports}};
}

std::string limitText(double v) {
    if (std::abs(v) >= kNoStop) return v < 0 ? "-inf" : "+inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

} // namespace

int runMachines(const MachinesOptions& o) {
    const std::vector<const MachineModule*> all = machines();
    if (o.json) {
        json::Array list;
        for (const MachineModule* m : all)
            list.push_back(machineJson(*m));
        std::fputs(json::write(json::Object{{"machines", list}}).c_str(), stdout);
        return kOk;
    }
    for (const MachineModule* m : all) {
        std::printf("%s: %s\n", m->id().c_str(), m->title().c_str());
        for (const AxisInfo& a : m->axes(m->defaultJob()))
            std::printf("  axis %-22s %-4s [%s, %s]  %s command\n", a.name.c_str(),
                        unitSymbol(a.unit), limitText(a.min).c_str(), limitText(a.max).c_str(),
                        commandModeName(a.mode));
        for (const ExportInfo& e : m->exports())
            std::printf("  export %-14s %s (%s)\n", e.id.c_str(), e.title.c_str(),
                        e.default_name.c_str());
    }
    return kOk;
}

int runUpgrade(const UpgradeOptions& o) {
    std::string text;
    try {
        text = readTextFile(o.job);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cutcell-cli upgrade: %s\n", e.what());
        return kFailure;
    }
    std::string upgraded;
    try {
        upgraded = upgradeJobText(text);
        (void)parseJob(upgraded); // the new file must load as it is (ranges included)
    } catch (const std::exception& e) {
        std::fprintf(stderr, "invalid job: %s\n", e.what());
        return kInvalidJob;
    }
    try {
        writeFileAtomically(o.out, upgraded);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cutcell-cli upgrade: %s\n", e.what());
        return kFailure;
    }
    std::printf("wrote %s (schema 2, %zu bytes)\n", o.out.c_str(), upgraded.size());
    return kOk;
}

} // namespace cutcell::cli
