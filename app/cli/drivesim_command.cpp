// cutcell-cli drivesim: the job's machine's CAN cell played on a bus (the simulator of
// devices/canopen/drive_simulator.h: its CiA 402 drives and CiA 406 encoders, as
// devices/machines/can_cells.h builds them) for tests and demos, with fault injection by flags.
#include "cli_commands.h"

#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/canopen/emcy.h"
#include "devices/machines/can_cells.h"

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

} // namespace

int runDriveSim(const DriveSimOptions& o) {
    // main.cpp has checked every value against its range.
    Job job = defaultJob();
    int code = kOk;
    if (!o.job.empty() && !loadJobArg(o.job, job, &code)) return code;
    const std::string& nodesText = o.nodes_text;
    // The machine's whole cell, or the drives --nodes names.
    CanCellConfig cell;
    if (std::string why; !makeCanCell(job, job.sim.period_s, nullptr, &cell, &why)) {
        std::fprintf(stderr, "cutcell-cli drivesim: the job's machine has no CAN cell: %s\n",
                     why.c_str());
        return kUsage;
    }
    std::vector<DriveNodeConfig> drives = cell.sim_drives;
    std::vector<EncoderNodeConfig> encoders = cell.sim_encoders;
    if (!nodesText.empty()) {
        try {
            drives = canCellDriveNodes(job, o.nodes);
        } catch (const std::invalid_argument& e) {
            std::fprintf(stderr, "cutcell-cli drivesim: --nodes = \"%s\": %s\n", nodesText.c_str(),
                         e.what());
            return kUsage;
        }
        encoders.clear();
    }
    std::vector<int> ids;
    for (const DriveNodeConfig& d : drives)
        ids.push_back(d.node);
    for (const EncoderNodeConfig& e : encoders)
        ids.push_back(e.node);
    FaultInjection faults;
    faults.fault_after_s = o.fault_after_s.value_or(faults.fault_after_s);
    faults.heartbeat_stop_after_s =
        o.heartbeat_stop_after_s.value_or(faults.heartbeat_stop_after_s);
    faults.torque_loss_after_s = o.following_error_after_s.value_or(faults.torque_loss_after_s);
    faults.refuse_sdo_index = o.refuse_object.value_or(0);
    const double duration = o.duration_s;
    if (o.fault_code) {
        faults.fault_code = *o.fault_code;
        if (faults.fault_after_s < 0) faults.fault_after_s = 0;
    }
    int faultNode = ids.front();
    if (o.fault_node) {
        faultNode = *o.fault_node;
        if (std::find(ids.begin(), ids.end(), faultNode) == ids.end()) {
            std::fprintf(
                stderr,
                "cutcell-cli drivesim: --fault-node = %d is not one of the simulated nodes\n",
                faultNode);
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
    if (!o.plugin.empty()) config.plugin = QString::fromStdString(o.plugin);
    if (!o.interface.empty()) config.interface = QString::fromStdString(o.interface);
    config.nodes = drives;
    config.encoders = encoders;
    for (DriveNodeConfig& n : config.nodes)
        if (n.node == faultNode) n.faults = faults;
    DriveSimulator sim(config);
    if (!sim.start()) {
        std::fprintf(stderr, "cutcell-cli drivesim: %s\n", qPrintable(sim.errorText()));
        return kFailure;
    }
    std::printf("drivesim: ready: %zu CiA 402 node(s)%s %s on %s %s\n", drives.size(),
                encoders.empty()
                    ? ""
                    : (" + " + std::to_string(encoders.size()) + " CiA 406 encoder(s)").c_str(),
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
            // An encoder (CiA 406) has no CiA 402 state machine: its NMT state alone.
            std::printf("node %d: %s, %s%s%s\n", s.node, toString(s.nmt),
                        s.encoder ? "encoder" : toString(s.state), s.error_code ? ", error " : "",
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
