#pragma once
// A simulated pipe-robot cell (six simulated drives + torch) around a fast-clock motion
// engine, with helpers that drive it into each state and collect its events.
#include "core/engine/motion_engine.h"
#include "core/job/default_job.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/pipe_robot_program.h"
#include "devices/sim/simulated_drive.h"
#include "devices/sim/simulated_torch.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace cutcell::test {

// The default job's plan and program, built once for all tests.
const Job& testJob();
const CutPlan& testPlan();
std::shared_ptr<const MotionProgram> testProgram();
// The same cell with a quick cut (40 mm/s, no minimum run time): for tests that only need to
// pass through the states (the state-machine table runs a whole job per cell).
std::shared_ptr<const MotionProgram> quickProgram();

struct CellOptions {
    StopCategory category = StopCategory::Cat0;
    std::string runs_dir;        // empty: no run log
    double chuck_start_deg = 30; // away from the reference, so homing takes a while
    std::uint32_t telemetry_every = 1;
    ClockMode clock = ClockMode::AsFastAsPossible;
    bool quick = false; // quickProgram() and a faster home speed
    // Another job and its program (both or neither; null: testJob() and the program above).
    const Job* job = nullptr;
    std::shared_ptr<const MotionProgram> program;
};

class SimCell {
  public:
    explicit SimCell(const CellOptions& o = {});

    MotionEngine& engine() { return *engine_; }
    SimulatedDrive& drive(int i) { return *drives_[static_cast<size_t>(i)]; }
    SimulatedTorch& torch() { return torch_; }

    // Runs cycles, collecting events (and dropping telemetry unless kept). Returns the state.
    EngineState run(std::uint64_t cycles, EngineState until);
    EngineState cycleOnce() { return run(1, EngineState::Idle); }
    // Runs until the state is reached (fails the test after max cycles).
    void runUntil(EngineState s, std::uint64_t max = 200000);

    // Into a state (from a fresh cell).
    void toReady(bool homed);
    void toHoming();
    void toJogging();
    void toRunning();              // Start accepted (approach phase)
    void toCutting(double path_s); // on the path, path_s into the cut
    void toPaused();
    void toCompleted();
    void toEmergencyStop();
    void toFault();

    std::vector<EngineEvent> events; // every event so far
    std::vector<TelemetrySample> telemetry;
    bool keepTelemetry = false;
    // Text of the events since index `from`.
    std::string eventText(size_t from = 0) const;
    bool drivesAllDisabled();

    const std::shared_ptr<const MotionProgram>& program() const { return program_; }

  private:
    std::shared_ptr<const MotionProgram> program_;
    std::vector<std::unique_ptr<SimulatedDrive>> drives_;
    SimulatedTorch torch_;
    std::unique_ptr<MotionEngine> engine_;
};

} // namespace cutcell::test
