#pragma once
// The bus's threads on the real-time scheduler. Every frame of a cycle passes the CAN master's
// thread (RPDOs and SYNC out, TPDOs in), and on a simulated bus also the virtualcan server's
// thread and the drive simulator's: on the normal scheduler a loaded host holds them for
// 10-20 ms (measured: flying saw over virtualcan with both cores busy, TPDOs up to 11 cycles
// of 2 ms late), a real-time engine cycle keeps running meanwhile and sees its feedback stop.
// The engine thread keeps the highest priority (80 by default); these come just below it.
//
// Threading contract: call on the thread to raise; never blocks.

namespace cutcell::canopen {

inline constexpr int kMasterThreadPriority = 70;    // CAN master: the cycle's frames
inline constexpr int kBusHostThreadPriority = 70;   // virtualcan server (relays every frame)
inline constexpr int kSimulatorThreadPriority = 65; // simulated drives and encoders

// SCHED_FIFO at `priority` for the calling thread when the process may (CAP_SYS_NICE or an
// RLIMIT_RTPRIO); false (the thread stays where it was) otherwise.
bool raiseCallingThreadToFifo(int priority);

} // namespace cutcell::canopen
