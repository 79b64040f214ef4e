// The profile cutter's simulated machine: A and X steppers behind the pulse card, and the
// torch (ProfileCutterRig).
#include "devices/machines/profile_cutter/profile_cutter_rig.h"
#include "devices/machines/sim_rigs.h"

namespace cutcell {
namespace {

class ProfileCutterSimRig : public MachineSimRig {
  public:
    ProfileCutterSimRig(const Job& job, const MotionProgram& program) : rig_(job, program) {}
    EngineDevices devices() override { return rig_.devices(); }
    void configure(EngineConfig& config) const override { rig_.configure(config); }
    void addToReport(json::Value& doc) const override {
        auto& r = const_cast<ProfileCutterRig&>(rig_);
        doc.set("pulses", json::Object{{"a_position", static_cast<double>(r.a().pulsePosition())},
                                       {"a_sent", static_cast<double>(r.a().pulsesSent())},
                                       {"x_position", static_cast<double>(r.x().pulsePosition())},
                                       {"x_sent", static_cast<double>(r.x().pulsesSent())},
                                       {"rate_limited_cycles",
                                        static_cast<double>(r.a().rateLimitedCycles() +
                                                            r.x().rateLimitedCycles())}});
    }
    std::string summary(const std::string& outcome) const override {
        auto& r = const_cast<ProfileCutterRig&>(rig_);
        return outcome + ": A " + std::to_string(r.a().pulsePosition()) + " pulses (" +
               std::to_string(r.a().pulsesSent()) + " sent), X " +
               std::to_string(r.x().pulsePosition()) + " pulses (" +
               std::to_string(r.x().pulsesSent()) + " sent), card at its limit " +
               std::to_string(r.a().rateLimitedCycles() + r.x().rateLimitedCycles()) + " cycles";
    }
    std::string description() const override {
        return "Simulated profile cutter: A and X steppers + torch";
    }

  private:
    ProfileCutterRig rig_;
};

} // namespace

std::unique_ptr<MachineSimRig> makeProfileCutterSimRig(const Job& job,
                                                       const MotionProgram& program) {
    return std::make_unique<ProfileCutterSimRig>(job, program);
}

} // namespace cutcell
