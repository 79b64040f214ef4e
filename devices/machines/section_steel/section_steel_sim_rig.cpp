// The section-steel cell's simulated devices: eight simulated drives (the job's PID and joint
// plant per axis, position-commanded by the engine) and a simulated torch.
#include "core/machines/section_steel/section_steel_spec.h"
#include "devices/machines/sim_rigs.h"
#include "devices/sim/simulated_drive.h"
#include "devices/sim/simulated_torch.h"

#include <array>
#include <stdexcept>

namespace cutcell {
namespace {

using section_steel::kSteelAxes;
using section_steel::SectionSteelSpec;

class SectionSteelSimRig : public MachineSimRig {
  public:
    SectionSteelSimRig(const Job& job, const MotionProgram& program) : period_(job.sim.period_s) {
        const SectionSteelSpec* spec = job.machine_spec.as<SectionSteelSpec>();
        if (!spec) throw std::invalid_argument("the job holds no section-steel machine section");
        for (size_t i = 0; i < drives_.size(); ++i) {
            SimulatedDriveConfig dc;
            dc.gains = spec->controller[i];
            dc.plant = spec->plant[i];
            dc.period_s = job.sim.period_s;
            dc.initial_position = program.reference[static_cast<int>(i)];
            drives_[i] = std::make_unique<SimulatedDrive>(dc);
        }
    }
    EngineDevices devices() override {
        EngineDevices d;
        for (size_t i = 0; i < drives_.size(); ++i)
            d.axes[i] = drives_[i].get();
        d.torch = &torch_;
        return d;
    }
    void configure(EngineConfig& config) const override { config.period_s = period_; }
    std::string description() const override { return "Simulated cell: 8 drives + torch"; }

  private:
    double period_;
    std::array<std::unique_ptr<SimulatedDrive>, kSteelAxes> drives_;
    SimulatedTorch torch_;
};

} // namespace

std::unique_ptr<MachineSimRig> makeSectionSteelSimRig(const Job& job,
                                                      const MotionProgram& program) {
    return std::make_unique<SectionSteelSimRig>(job, program);
}

} // namespace cutcell
