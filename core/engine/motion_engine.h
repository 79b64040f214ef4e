#pragma once
// The motion engine: a fixed-period control cycle on its own thread
//   read devices -> state machine / trajectory -> write devices
// with a real-time clock (paced to the wall clock) or as fast as possible (same code path).
//
// Threading contract:
//  - Commands may be sent from any thread; they go through a bounded lock-free queue and
//    return at once (false if the queue is full). Refusals come back as events.
//  - emergencyStop() additionally sets an atomic checked at the top of every cycle.
//  - Telemetry and events leave through bounded single-producer/single-consumer rings: one
//    consumer thread (e.g. the GUI timer) drains them with popTelemetry()/popEvent(). Samples
//    lost because the ring was full are counted in CycleStats, never hidden.
//  - The cycle itself does not allocate, lock or block. Loading a program happens outside the
//    cycle: load() hands over a shared_ptr that the engine swaps in at the next cycle.
#include "core/devices/device_interfaces.h"
#include "core/engine/engine_types.h"
#include "core/engine/motion_program.h"
#include "core/job/job.h"

#include <array>
#include <memory>

namespace cutcell {

struct EngineDevices {
    std::array<AxisDrive*, kAxisCount> axes{}; // null for axes the machine does not have
    Torch* torch = nullptr;
};

struct EngineConfig {
    double period_s = 0.001;
    ClockMode clock = ClockMode::RealTime;
    EngineSpec spec;          // stop category, feed hold, limits, runs dir
    std::array<PidGains, kAxisCount> gains{}; // for drives that close the loop themselves: unused
};

class MotionEngine {
  public:
    MotionEngine(EngineDevices devices, EngineConfig config);
    ~MotionEngine();
    MotionEngine(const MotionEngine&) = delete;
    MotionEngine& operator=(const MotionEngine&) = delete;

    // Thread control. In AsFastAsPossible mode the thread runs cycles back to back.
    void startThread();
    void stopThread();
    // Runs cycles on the calling thread (tests, CLI) until the predicate state is reached or
    // max_cycles have run; no thread must be started. Returns the state reached.
    EngineState runCycles(std::uint64_t max_cycles, EngineState until);

    // Commands (any thread, non-blocking).
    bool load(std::shared_ptr<const MotionProgram> program);
    bool enable();
    bool disable();
    bool home();
    bool jog(int axis, double delta); // relative move of one axis while Ready
    bool start();
    bool feedHold();
    bool resume();
    bool setOverride(double fraction); // 0.10 .. 1.50
    bool abort();
    bool emergencyStop();              // also sets the atomic request at once
    bool releaseEmergencyStop();       // the operator pulled the mushroom button back out
    bool reset();

    // Consumer side (one thread).
    bool popTelemetry(TelemetrySample& out);
    bool popEvent(EngineEvent& out);

    // Snapshot readable from any thread.
    EngineState state() const;
    CycleStats cycleStats() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace cutcell
