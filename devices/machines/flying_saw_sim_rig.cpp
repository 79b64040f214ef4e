// The flying saw's simulated cell: the pipe line and its roller encoder (sensor 0, with the
// job's wander, steps, noise, quantisation and slip), four simulated servo drives (carriage,
// turntable, two radial feeds) and the saw as the process tool. The line sensor also measures
// every cut on the pipe (carriage's true position - line's true travel while the blade is in
// the wall) and plays the length gauge after the saw, reporting each piece to the source.
#include "core/machines/flying_saw/cut_length_meter.h"
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/flying_saw/flying_saw_program.h"
#include "core/machines/flying_saw/pipe_line_sim.h"
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

// The line encoder as the engine reads it, measuring the cuts on the way (engine thread).
class MeasuringLine : public SensorInput {
  public:
    MeasuringLine(const FlyingSawSpec& s, const MotionProgram& program, FlyingSawSource* source,
                  SimulatedDrive* carriage)
        : spec_(s), line_(lineConfig(s, program)), source_(source), carriage_(carriage),
          meter_(s.pieceCount() + 8), gauge_(static_cast<size_t>(s.pieceCount()) + 8, 0.0),
          ordered_(static_cast<size_t>(s.pieceCount()) + 8, 0.0) {}

    SensorReading read(double now_s) override {
        const SensorReading r = line_.read(now_s);
        meter_.feed(source_->bladeInWall(), source_->cutIndex(),
                    carriage_->truePosition() - line_.position(), now_s);
        // A cut closed: its piece's ordered length; the gauge reports it `delay` pieces later.
        while (seen_ < meter_.cuts().size()) {
            const CutRecord& c = meter_.cuts()[seen_];
            const size_t k = static_cast<size_t>(c.index);
            if (c.index >= 1 && k < ordered_.size()) {
                ordered_[k] = source_->orderedLength(c.index);
                if (seen_ >= 1)
                    gauge_[k] =
                        meter_.cuts()[seen_ - 1].position_mm - c.position_mm - spec_.blade_kerf_mm;
                const int report = c.index - spec_.gauge_delay_pieces;
                if (spec_.gauge_enabled && report >= 1 && gauge_[static_cast<size_t>(report)] > 0)
                    source_->reportGauge(report, gauge_[static_cast<size_t>(report)]);
            }
            ++seen_;
        }
        return r;
    }
    std::vector<PieceRecord> pieces() const {
        return meter_.pieces(spec_.blade_kerf_mm, [&](int p) {
            return p >= 0 && static_cast<size_t>(p) < ordered_.size()
                       ? ordered_[static_cast<size_t>(p)]
                       : 0.0;
        });
    }

  private:
    FlyingSawSpec spec_;
    PipeLineSim line_;
    FlyingSawSource* source_;
    SimulatedDrive* carriage_;
    CutLengthMeter meter_;
    std::vector<double> gauge_, ordered_;
    size_t seen_ = 0;
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
        // The drives reach a set-point one period after it is written: at 1 m/s that alone is
        // 1 mm of "error"; the carriage's lag in its ramps adds about as much.
        config.following_error_limit_mm = 10;
        // The fast radial feed moves ~0.01 mm in its first cycle, before the feedback (read
        // before the write) can show it: a frozen encoder is still caught within a few cycles.
        config.frozen_feedback_travel = 0.05;
    }
    void addToReport(json::Value& doc) const override {
        const std::vector<PieceRecord> p = line_->pieces();
        const LengthStats s = lengthStats(p, spec_.tolerance_mm);
        json::Array rows;
        for (const PieceRecord& r : p)
            rows.emplace_back(json::Object{{"piece", r.piece},
                                           {"ordered_mm", r.ordered_mm},
                                           {"length_mm", r.length_mm},
                                           {"error_mm", r.error_mm},
                                           {"cut_spread_mm", r.spread_mm}});
        doc.set("cut_lengths", json::Object{{"pieces_measured", s.count},
                                            {"error_mm_mean", s.mean},
                                            {"error_mm_std", s.std},
                                            {"error_mm_max_abs", s.max_abs},
                                            {"cpk", s.cpk},
                                            {"tolerance_mm", spec_.tolerance_mm},
                                            {"pieces", rows}});
    }
    std::string summary(const std::string& outcome) const override {
        const LengthStats s = lengthStats(line_->pieces(), spec_.tolerance_mm);
        char b[200];
        std::snprintf(b, sizeof b,
                      ": %d pieces, length error mean %.4f mm, std %.4f mm, max %.4f mm", s.count,
                      s.mean, s.std, s.max_abs);
        return outcome + b;
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
