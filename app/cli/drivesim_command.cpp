// cutcell-cli drivesim: CiA 402 slave nodes on a CAN bus (the simulator of
// devices/canopen/drive_simulator.h) for tests and demos, with fault injection by flags.
#include "cli_commands.h"

#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/canopen/emcy.h"

#include "qt_app.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <pthread.h>

namespace cutcell::cli {
namespace {

using namespace cutcell::canopen;

// "1-6", "1,3,5" or "2-3,7": node ids 1..127.
bool parseNodes(const std::string& text, std::vector<int>& out, std::string& error) {
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
            error = "--nodes = \"" + text + "\": \"" + part +
                    "\" is not a node id or range within 1..127";
            return false;
        }
        for (long n = a; n <= b; ++n)
            out.push_back(static_cast<int>(n));
        if (comma == std::string::npos) break;
        at = comma + 1;
    }
    return true;
}

bool parseSeconds(const Args& args, const std::string& name, double& out, std::string& error) {
    const std::string v = option(args, name);
    if (v.empty()) return true;
    char* end = nullptr;
    out = std::strtod(v.c_str(), &end);
    if (*end != '\0' || !(out >= 0) || out > 1e6) {
        error = name + " = \"" + v + "\" s is not a time in [0, 1e6] s";
        return false;
    }
    return true;
}

} // namespace

int runDriveSim(const Args& args) {
    const std::vector<std::string> valueOptions{"--nodes",
                                                "--plugin",
                                                "--interface",
                                                "--fault-node",
                                                "--fault-code",
                                                "--fault-after",
                                                "--heartbeat-stop-after",
                                                "--following-error-after",
                                                "--duration"};
    Job job = defaultJob();
    const auto pos = positionals(args, valueOptions);
    if (!pos.empty()) {
        try {
            job = loadJobFile(pos.front());
        } catch (const JobError& e) {
            std::fprintf(stderr, "invalid job: %s\n", e.what());
            return kInvalidJob;
        }
    }
    std::string error;
    std::vector<int> ids;
    const std::string nodesText = option(args, "--nodes");
    if (nodesText.empty())
        ids.assign(job.devices.node_ids.begin(), job.devices.node_ids.end());
    else if (!parseNodes(nodesText, ids, error)) {
        std::fprintf(stderr, "cutcell-cli drivesim: %s\n", error.c_str());
        return kUsage;
    }
    FaultInjection faults;
    double duration = 0;
    if (!parseSeconds(args, "--fault-after", faults.fault_after_s, error) ||
        !parseSeconds(args, "--heartbeat-stop-after", faults.heartbeat_stop_after_s, error) ||
        !parseSeconds(args, "--following-error-after", faults.torque_loss_after_s, error) ||
        !parseSeconds(args, "--duration", duration, error)) {
        std::fprintf(stderr, "cutcell-cli drivesim: %s\n", error.c_str());
        return kUsage;
    }
    const std::string code = option(args, "--fault-code");
    if (!code.empty()) {
        char* end = nullptr;
        const unsigned long c = std::strtoul(code.c_str(), &end, 0);
        if (*end != '\0' || c == 0 || c > 0xFFFF) {
            std::fprintf(stderr,
                         "cutcell-cli drivesim: --fault-code = \"%s\" is not an EMCY code in "
                         "0x0001..0xFFFF\n",
                         code.c_str());
            return kUsage;
        }
        faults.fault_code = static_cast<std::uint16_t>(c);
        if (faults.fault_after_s < 0) faults.fault_after_s = 0;
    }
    int faultNode = ids.front();
    if (const std::string fn = option(args, "--fault-node"); !fn.empty()) {
        faultNode = std::atoi(fn.c_str());
        if (std::find(ids.begin(), ids.end(), faultNode) == ids.end()) {
            std::fprintf(
                stderr,
                "cutcell-cli drivesim: --fault-node = %s is not one of the simulated nodes\n",
                fn.c_str());
            return kUsage;
        }
    }

    // SIGINT/SIGTERM are taken synchronously below; block them before any thread starts.
    sigset_t stopSignals;
    sigemptyset(&stopSignals);
    sigaddset(&stopSignals, SIGINT);
    sigaddset(&stopSignals, SIGTERM);
    // SIGUSR1: the fault node raises --fault-code (0x1000 generic if none) now; SIGUSR2: it
    // stops its heartbeats now. For tests that need a fault at a given moment of a run.
    sigaddset(&stopSignals, SIGUSR1);
    sigaddset(&stopSignals, SIGUSR2);
    pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);
    const std::uint16_t signalledFault = faults.fault_code ? faults.fault_code : 0x1000;

    const auto app = ensureQCoreApplication();
    DriveSimulatorConfig config;
    if (const std::string p = option(args, "--plugin"); !p.empty())
        config.plugin = QString::fromStdString(p);
    if (const std::string i = option(args, "--interface"); !i.empty())
        config.interface = QString::fromStdString(i);
    config.nodes = nodesFromJob(job, ids);
    for (DriveNodeConfig& n : config.nodes)
        if (n.node == faultNode) n.faults = faults;
    DriveSimulator sim(config);
    if (!sim.start()) {
        std::fprintf(stderr, "cutcell-cli drivesim: %s\n", qPrintable(sim.errorText()));
        return kFailure;
    }
    std::printf("drivesim: ready: %zu CiA 402 node(s) %s on %s %s\n", ids.size(),
                nodesText.empty() ? "from the job" : nodesText.c_str(), qPrintable(config.plugin),
                qPrintable(config.interface));
    std::fflush(stdout);

    // Report every change of a node's NMT or CiA 402 state until a stop signal (or --duration).
    std::map<int, std::pair<NmtState, Cia402State>> last;
    const timespec poll{0, 50'000'000};
    timespec start{};
    clock_gettime(CLOCK_MONOTONIC, &start);
    for (;;) {
        const int sig = sigtimedwait(&stopSignals, nullptr, &poll);
        if (sig == SIGUSR1) {
            sim.injectFault(faultNode, signalledFault);
        } else if (sig == SIGUSR2) {
            sim.stopHeartbeat(faultNode);
        } else if (sig > 0) {
            break;
        }
        for (const SimNodeSnapshot& s : sim.snapshot()) {
            auto& [nmt, state] = last[s.node];
            if (nmt == s.nmt && state == s.state) continue;
            nmt = s.nmt;
            state = s.state;
            std::printf("node %d: %s, %s%s%s\n", s.node, toString(s.nmt), toString(s.state),
                        s.error_code ? ", error " : "",
                        s.error_code ? emcyText(s.error_code).c_str() : "");
        }
        std::fflush(stdout);
        timespec now{};
        clock_gettime(CLOCK_MONOTONIC, &now);
        if (duration > 0 && static_cast<double>(now.tv_sec - start.tv_sec) +
                                    static_cast<double>(now.tv_nsec - start.tv_nsec) * 1e-9 >=
                                duration)
            break;
    }
    sim.stop();
    std::printf("drivesim: stopped\n");
    return kOk;
}

} // namespace cutcell::cli
