// The flying saw's cut lengths on its CAN cell. The simulated rig measures a cut on the pipe
// from the true carriage and line positions; over the bus the cell's own instruments give it:
// q = carriage feedback (CiA 402 position actual, 1 um counts) - line encoder (CiA 406 position
// value, the roller's 0.05 mm pulses), both sampled at the same SYNC. Only such pairs are used:
// a cycle whose carriage TPDO came late (age_cycles > 0) or whose encoder TPDO did not come
// (position unchanged while the line runs) would pair two SYNCs and be off by the line's
// travel in a cycle (2 mm at 60 m/min, 2 ms). What the roller does not see (slip) the figure
// does not see either: the encoder is the reference on the CAN cell (the gauge's scale
// correction still runs, fed by these lengths).
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/flying_saw/flying_saw_source.h"
#include "devices/machines/can_cells.h"
#include "devices/machines/flying_saw/saw_cut_recorder.h"

#include <stdexcept>

namespace cutcell {
namespace {

// The carriage drive as the engine reads it, its last feedback kept for the line's read.
class WatchedDrive : public AxisDrive {
  public:
    explicit WatchedDrive(AxisDrive* inner) : inner_(inner) {}
    void activate() override { inner_->activate(); }
    void deactivate() override { inner_->deactivate(); }
    void quickStop() override { inner_->quickStop(); }
    void faultReset() override { inner_->faultReset(); }
    DriveFeedback read(double now_s) override { return last_ = inner_->read(now_s); }
    void write(double q) override { inner_->write(q); }
    void writeVelocity(double v) override { inner_->writeVelocity(v); }
    void writeTorque(double t) override { inner_->writeTorque(t); }
    bool setCommandMode(AxisCommandMode m) override { return inner_->setCommandMode(m); }
    AxisCommandMode commandMode() const override { return inner_->commandMode(); }
    const DriveFeedback& last() const { return last_; }

  private:
    AxisDrive* inner_;
    DriveFeedback last_;
};

// The line encoder as the engine reads it (after the axes: the engine reads the drives first),
// measuring the cuts on the way.
class MeasuringCanLine : public SensorInput {
  public:
    MeasuringCanLine(SensorInput* inner, const WatchedDrive* carriage, const FlyingSawSpec& s,
                     FlyingSawSource* source)
        : inner_(inner), carriage_(carriage), cuts_(s, source) {}
    SensorReading read(double now_s) override {
        const SensorReading r = inner_->read(now_s);
        const DriveFeedback& c = carriage_->last();
        const bool fresh =
            r.valid && r.age_cycles == 0 && r.position != lastLine_ && c.age_cycles == 0;
        lastLine_ = r.position;
        if (fresh) cuts_.feed(c.position - r.position, now_s);
        return r;
    }
    const SawCutRecorder& cuts() const { return cuts_; }

  private:
    SensorInput* inner_;
    const WatchedDrive* carriage_;
    SawCutRecorder cuts_;
    double lastLine_ = 0;
};

class FlyingSawCanMeter : public CanCellMeter {
  public:
    FlyingSawCanMeter(const FlyingSawSpec& spec, FlyingSawSource* source)
        : spec_(spec), source_(source) {}
    void attach(EngineDevices& devices) override {
        if (!devices.axes[0] || !devices.sensors[0])
            throw std::invalid_argument("flying saw CAN meter: no carriage or line encoder");
        carriage_ = std::make_unique<WatchedDrive>(devices.axes[0]);
        line_ =
            std::make_unique<MeasuringCanLine>(devices.sensors[0], carriage_.get(), spec_, source_);
        devices.axes[0] = carriage_.get();
        devices.sensors[0] = line_.get();
    }
    void addToReport(json::Value& doc) const override {
        if (line_) line_->cuts().addToReport(doc);
    }
    std::string summary(const std::string& outcome) const override {
        return line_ ? line_->cuts().summary(outcome) : outcome;
    }

  private:
    FlyingSawSpec spec_;
    FlyingSawSource* source_;
    std::unique_ptr<WatchedDrive> carriage_;
    std::unique_ptr<MeasuringCanLine> line_;
};

} // namespace

std::unique_ptr<CanCellMeter> makeFlyingSawCanMeter(const Job& job, const MotionProgram& program) {
    auto* source = dynamic_cast<FlyingSawSource*>(program.source.get());
    const auto* spec = job.machine_spec.as<FlyingSawSpec>();
    if (!source || !spec) return nullptr;
    return std::make_unique<FlyingSawCanMeter>(*spec, source);
}

} // namespace cutcell
