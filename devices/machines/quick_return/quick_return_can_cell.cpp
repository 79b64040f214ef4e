// The quick-return cutter's CAN cell: the crank drive in CST with the Whitworth mechanism
// behind it, and the slider's linear scale as a CiA 406 encoder.
#include "core/machines/quick_return/crank_plant.h"
#include "core/machines/quick_return/quick_return_spec.h"
#include "devices/machines/can_cell_machine.h"

#include <cmath>
#include <memory>
#include <numbers>

namespace cutcell {
namespace {

// The mechanism behind the crank drive: the crank's torque steps the Whitworth dynamics
// (configuration-dependent inertia, gravity, the contact force over the workpiece, friction,
// the disturbance torque), as QuickReturnCrankDrive does in process.
class CrankMechanics : public canopen::TorquePlant {
  public:
    CrankMechanics(const quick_return::ExperimentSetup& s, double q0)
        : s_(s), plant_(s.law.dims, s.plant) {
        plant_.setState(q0, 0);
    }
    double position() const override { return plant_.state().q; }
    double velocity() const override { return plant_.state().dq; }
    double step(double torque, double h) override {
        const double dist =
            s_.disturbance_amplitude * std::sin(2 * std::numbers::pi * s_.disturbance_hz * t_);
        t_ += h;
        const bool on = torque != 0;
        return plant_.step(torque, on ? dist : 0.0, h);
    }
    double ratedTorque() const override { return s_.plant.torque_limit; }
    double sliderMm() const { return 1000 * plant_.sliderPosition(); }

  private:
    quick_return::ExperimentSetup s_;
    quick_return::CrankPlant plant_;
    double t_ = 0;
};

} // namespace

bool fillQuickReturnCanCell(CanCellBuilder& b, std::string* error) {
    const auto* qr = b.job.machine_spec.as<QuickReturnSpec>();
    if (!qr) {
        if (error) *error = "the job holds no quick-return section";
        return false;
    }
    quick_return::ExperimentSetup s;
    if (const Outcome set = buildSetup(*qr, &s); !set.ok()) {
        if (error) *error = set.message;
        return false;
    }
    s.plant.contact = qr->experiment == quick_return::Experiment::Cutting;
    const double q0 = b.program ? b.program->start_position[0] : s.law.stroke.q_bottom + 0.01;
    auto crank = std::make_shared<CrankMechanics>(s, q0);
    canopen::DriveNodeConfig d = b.driveNode(0, {}, {});
    d.mechanics = crank;
    d.plant.torque_limit_nm = s.plant.torque_limit;
    b.cell.sim_drives.push_back(d);
    // The slider's linear scale (mm) on the mechanism the crank drive moves.
    b.addEncoder(0, 1.0 / (1000 * qr->scale_resolution),
                 [crank](double) { return crank->sliderMm(); });
    return true;
}

} // namespace cutcell
