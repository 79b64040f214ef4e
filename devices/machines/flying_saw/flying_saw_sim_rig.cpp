// The flying saw's simulated cell: the pipe line and its roller encoder (sensor 0, with the
// job's wander, steps, noise, quantisation and slip), four simulated servo drives (carriage,
// turntable, two radial feeds) and the saw as the process tool. The line sensor also measures
// every cut on the pipe (carriage's true position - line's true travel while the blade is in
// the wall) and plays the length gauge after the saw, reporting each piece to the source.
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/flying_saw/flying_saw_program.h"
#include "core/machines/flying_saw/pipe_line_sim.h"
#include "devices/machines/flying_saw/saw_cut_recorder.h"
#include "devices/machines/sim_rigs.h"
#include "devices/sim/simulated_drive.h"
#include "devices/sim/simulated_saw.h"

#include <array>
#include <cstdio>
#include <stdexcept>

namespace cutcell {
namespace {

PipeLineConfig lineConfig(const FlyingSawSpec& s, const MotionProgram& program) {
    PipeLineConfig c;
    c.speed_mm_s = s.lineSpeedMmS();
    c.resolution_mm = s.encoderResolutionMm();
    c.sim = s.line_sim;
    c.duration_s = 2 * program.cut_time_s + 600;
    return c;
}

// The line encoder as the engine reads it, measuring the cuts on the way (engine thread): the
// carriage's and the line's true positions.
class MeasuringLine : public SensorInput {
  public:
    MeasuringLine(const FlyingSawSpec& s, const MotionProgram& program, FlyingSawSource* source,
                  SimulatedDrive* carriage)
        : line_(lineConfig(s, program)), carriage_(carriage), cuts_(s, source) {}

    SensorReading read(double now_s) override {
        const SensorReading r = line_.read(now_s);
        cuts_.feed(carriage_->truePosition() - line_.position(), now_s);
        return r;
    }
    const SawCutRecorder& cuts() const { return cuts_; }

  private:
    PipeLineSim line_;
    SimulatedDrive* carriage_;
    SawCutRecorder cuts_;
};

class FlyingSawSimRig : public MachineSimRig {
  public:
    FlyingSawSimRig(const Job& job, const MotionProgram& program)
        : spec_(flyingSawSpec(job)), period_(job.sim.period_s) {
        auto* source = dynamic_cast<FlyingSawSource*>(program.source.get());
        if (!source) throw std::invalid_argument("the program has no flying-saw source");
        for (size_t i = 0; i < drives_.size(); ++i) {
            SimulatedDriveConfig dc;
            dc.gains = sawAxisGains();
            dc.plant = sawAxisPlant();
            dc.period_s = job.sim.period_s;
            dc.initial_position = program.reference[static_cast<int>(i)];
            drives_[i] = std::make_unique<SimulatedDrive>(dc);
        }
        line_ = std::make_unique<MeasuringLine>(spec_, program, source, drives_[0].get());
    }
    EngineDevices devices() override {
        EngineDevices d;
        for (size_t i = 0; i < drives_.size(); ++i)
            d.axes[i] = drives_[i].get();
        d.sensors[0] = line_.get();
        d.torch = &saw_;
        return d;
    }
    void configure(EngineConfig& config) const override {
        config.period_s = period_;
        config.in_position_window = 1e-6; // mm / rad
        config.in_position_velocity = 1e-4;
        // The fast radial feed moves ~0.01 mm in its first cycle, before the feedback (read
        // before the write) can show it: a frozen encoder is still caught within a few cycles.
        config.frozen_feedback_travel = 0.05;
    }
    void addToReport(json::Value& doc) const override { line_->cuts().addToReport(doc); }
    std::string summary(const std::string& outcome) const override {
        return line_->cuts().summary(outcome);
    }
    std::string description() const override {
        return "Simulated flying saw: line encoder, carriage, turntable, 2 feeds + saw";
    }

  private:
    FlyingSawSpec spec_;
    double period_;
    std::array<std::unique_ptr<SimulatedDrive>, 4> drives_;
    std::unique_ptr<MeasuringLine> line_;
    SimulatedSaw saw_{0.5};
};

} // namespace

std::unique_ptr<MachineSimRig> makeFlyingSawSimRig(const Job& job, const MotionProgram& program) {
    return std::make_unique<FlyingSawSimRig>(job, program);
}

} // namespace cutcell
