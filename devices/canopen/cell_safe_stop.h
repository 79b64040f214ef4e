#pragma once
// The safe state of a cell whose drives are on a CANopen bus, for any ending of the program
// (see devices/process/safe_shutdown.h): torch off first (the engine's emergency stop switches
// it off at once), then every drive disabled with the frames on the bus (whatever the engine
// managed), then the line saying so in the run log (events.log) and on stderr.
#include <string>

namespace cutcell {
class MotionEngine;
}

namespace cutcell::canopen {

class CanOpenMaster;

// Either pointer may be null; tool: the machine's tool as its program names it (torch, saw,
// cutter: MotionProgram::terms.tool). Returns the logged line, e.g. "program ending (SIGTERM):
// saw off, 4 drives disabled (CiA 402 disable voltage + NMT pre-operational written to the bus)".
std::string safeStopCanCell(MotionEngine* engine, CanOpenMaster* master, const std::string& why,
                            const char* program, const std::string& tool);

} // namespace cutcell::canopen
