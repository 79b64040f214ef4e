#include "devices/canopen/cell_safe_stop.h"

#include "core/engine/motion_engine.h"
#include "devices/canopen/canopen_master.h"

#include <chrono>
#include <cstdio>
#include <thread>

namespace cutcell::canopen {

std::string safeStopCanCell(MotionEngine* engine, CanOpenMaster* master, const std::string& why,
                            const char* program, const std::string& tool) {
    using Clock = std::chrono::steady_clock;
    if (engine) {
        engine->emergencyStop();
        const auto until = Clock::now() + std::chrono::milliseconds(100);
        while (engine->state() != EngineState::EmergencyStop && Clock::now() < until)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    std::string what = engine ? (tool.empty() ? "tool" : tool) + " off, " : "";
    if (master)
        what += master->disableAllNow(200)
                    ? std::to_string(master->driveCount()) +
                          " drives disabled (CiA 402 disable voltage + NMT pre-operational "
                          "written to the bus)"
                    : "the CAN master did not answer within 200 ms: the drives stop on their "
                      "own when the master's heartbeat ends";
    const std::string line = "program ending (" + why + "): " + what;
    std::fprintf(stderr, "%s: %s\n", program, line.c_str());
    if (engine) {
        engine->logExternalEvent(Severity::Error, line);
        engine->flushRunLog(); // now: std::terminate aborts right after
    }
    return line;
}

} // namespace cutcell::canopen
