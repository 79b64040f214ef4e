// Range and consistency checks of the common part of a job, then the machine's own
// validation (its module). Each message names the key, the value with its unit and the limit,
// so the form or the CLI can show it as it is.
#include "core/job/issue_checker.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"

#include <algorithm>
#include <cmath>

namespace cutcell {
namespace {

// The bit rates of CiA 301 / CiA 102 (CAN FD aside).
constexpr int kCanBitRates[] = {10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000};

// A CiA 402 position (0x607A/0x6064) is a signed 32-bit count: an axis with a travel must not
// leave it anywhere on its travel. Continuous axes (the saw's turntable, the crank) are checked
// against the run's own reach before it starts on CAN drives (core/machine/counts_reach.h).
constexpr double kInt32Counts = 2147483647.0;
constexpr double kEndlessTravel = 1e8; // |limit| beyond this: the axis turns without end

void checkCounts(IssueChecker& c, const Job& job, int i, const AxisInfo* axis) {
    const std::string key = "devices.counts_per_unit[" + std::to_string(i) + "]";
    const double cpu = job.devices.counts_per_unit[static_cast<size_t>(i)];
    const char* unit = axis && axis->unit == AxisUnit::Linear ? "counts/mm" : "counts/deg";
    const size_t before = c.issues.size();
    c.positive(key, cpu, 1e-3, 1e9, unit);
    if (!axis || c.issues.size() != before) return;
    const double reach = std::max(std::fabs(axis->min), std::fabs(axis->max));
    if (reach >= kEndlessTravel || reach * cpu <= kInt32Counts) return;
    const char* u = unitSymbol(axis->unit);
    c.add(key, messageC("%s = %.6g %s: axis %d (%s) travels to %.6g %s, %.4g counts, beyond a "
                        "drive's 32-bit position (%.0f counts); at most %.6g %s",
                        key.c_str(), cpu, unit, i, axis->name.c_str(), reach, u, reach * cpu,
                        kInt32Counts, std::floor(kInt32Counts / reach * 1e3) / 1e3, unit));
}

void checkCommon(IssueChecker& c, const Job& job, const std::vector<AxisInfo>& axes, int axisCount,
                 int sensorCount) {
    c.range("sim.period_s", job.sim.period_s, 1e-4, 0.02, "s");
    c.range("sim.duration_s", job.sim.duration_s, 0.1, 3600, "s");
    c.range("engine.feed_hold_decel_s", job.engine.feed_hold_decel_s, 0.01, 10, "s");
    c.range("engine.following_error_limit_deg", job.engine.following_error_limit_deg, 0.001, 90,
            "deg");
    c.range("engine.home_speed_deg_s", job.engine.home_speed_deg_s, 0.1, 360, "deg/s");
    c.range("engine.following_error_limit_mm", job.engine.following_error_limit_mm, 0.001, 100,
            "mm");
    c.range("engine.home_speed_mm_s", job.engine.home_speed_mm_s, 0.1, 1000, "mm/s");
    if (std::find(std::begin(kCanBitRates), std::end(kCanBitRates), job.devices.bitrate_bps) ==
        std::end(kCanBitRates))
        c.add("devices.bitrate_bps",
              messageC("devices.bitrate_bps = %d bit/s is not a CAN bit rate: one of 10000, "
                       "20000, 50000, 125000, 250000, 500000, 800000, 1000000 bit/s",
                       job.devices.bitrate_bps));
    for (int i = 0; i < axisCount; ++i) {
        const int id = job.devices.node_ids[static_cast<size_t>(i)];
        if (id < 1 || id > 127)
            c.add("devices.node_ids",
                  messageC("devices.node_ids[%d] = %d is outside [1, 127]", i, id));
        for (int j = 0; j < i; ++j)
            if (job.devices.node_ids[static_cast<size_t>(j)] == id)
                c.add("devices.node_ids",
                      messageC("devices.node_ids[%d] = %d is used twice", i, id));
        checkCounts(c, job, i,
                    i < static_cast<int>(axes.size()) ? &axes[static_cast<size_t>(i)] : nullptr);
    }
    for (int k = 0; k < sensorCount; ++k) {
        const int id = sensorNodeId(job.devices, axisCount, k);
        if (id < 1 || id > 127)
            c.add("devices.sensor_node_ids",
                  messageC("devices.sensor_node_ids[%d] = %d is outside [1, 127]", k, id));
        for (int i = 0; i < axisCount; ++i)
            if (job.devices.node_ids[static_cast<size_t>(i)] == id)
                c.add("devices.sensor_node_ids",
                      messageC("devices.sensor_node_ids[%d] = %d is the node of axis %d "
                               "(devices.node_ids[%d])",
                               k, id, i, i));
        for (int j = 0; j < k; ++j)
            if (sensorNodeId(job.devices, axisCount, j) == id)
                c.add("devices.sensor_node_ids",
                      messageC("devices.sensor_node_ids[%d] = %d is used twice", k, id));
    }
    c.range("devices.heartbeat_timeout_ms", job.devices.heartbeat_timeout_ms, 10, 10000, "ms");
    if (job.devices.sync_counter_overflow == 1)
        c.add("devices.sync_counter_overflow",
              messageC("devices.sync_counter_overflow = 1 is reserved (CiA 301 0x1019): 0 for "
                       "no SYNC counter, or 2..240"));
}

} // namespace

std::vector<JobIssue> validateJob(const Job& job) {
    IssueChecker c;
    const std::string id = job.machine.empty() ? schema1DefaultMachine() : job.machine;
    const MachineModule* module = findMachine(id);
    if (!module) {
        c.add("machine.kind", messageC("machine.kind = %s is not one of %s",
                                       json::quote(id).c_str(), machineIdList().c_str()));
        checkCommon(c, job, {}, 0, 0); // no axes without a machine
        return c.issues;
    }
    const std::vector<AxisInfo> axes = module->axes(job);
    checkCommon(c, job, axes, static_cast<int>(axes.size()),
                static_cast<int>(module->sensorNames().size()));
    // The machine's issues keep their key relative to the section (the forms' field ids);
    // the message names the key as it stands in the file.
    for (JobIssue issue : module->validate(job)) {
        if (issue.message.rfind(issue.key, 0) == 0) issue.message = "machine." + issue.message;
        c.issues.push_back(issue);
    }
    if (job.devices.kind == DeviceKind::CanOpen)
        if (const Outcome can = module->canOpen(); !can.ok())
            c.add("devices.kind", messageC("devices.kind = \"canopen\": %s", can.message.c_str()));
    return c.issues;
}

} // namespace cutcell
