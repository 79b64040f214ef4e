#pragma once
// The 2-axis NC pipe profile cutter of seed 002: A (the pipe turning in the chuck, rotary) and
// X (the torch carriage, linear), stepper motors behind a pulse card; no CANopen drives.
//
// Its `machine` section: the pipe joint (main_pipe, branch_pipe, angle_deg, eccentricity_mm,
// cut: target, bevel_deg = 0, speed_mm_s, ramp_s, knot_spacing_mm), other_branches[] and
// profile_cutter { steps_per_rev_a, pulses_per_step_a, mm_per_pulse_x, max_pulse_rate_hz, pierce_s,
// x_travel_mm, branch_position_mm }.
#include "core/machine/machine_module.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_lead.h"
#include "core/machines/profile_cutter/stepper_schedule.h"

namespace cutcell {

inline constexpr const char* kProfileCutterId = "profile_cutter_2axis";

// MachinePlan::data of the profile cutter's plans.
struct ProfileCutterPlanData {
    ProfileCut cut;
    PulseSchedule schedule;
    ProfileLeads leads; // the lead-in / lead-out and torch heights (unused: none asked for)
};

class ProfileCutterModule : public MachineModule {
  public:
    std::string id() const override { return kProfileCutterId; }
    std::string title() const override { return "NC pipe profile cutter (A + X, steppers)"; }
    std::vector<AxisInfo> axes(const Job& job) const override;
    Job defaultJob() const override;
    void readSection(const json::Value& section, Job& job) const override;
    json::Value writeSection(const Job& job) const override;
    void migrateSchema1(json::Object& section) const override;
    std::vector<JobIssue> validate(const Job& job) const override;
    Outcome canOpen() const override;
    // The stepper and pulse scaling and the X travel, and the robot's data it shares; the
    // pierce time and the branch position are the setter's.
    bool isMachineParameter(const std::string& key) const override;
    MachinePlan plan(const Job& job, const std::string& jobText,
                     const PlanOptions& options) const override;
    std::vector<ExportInfo> exports() const override;
    std::string exportFile(const std::string& exportId, const Job& job,
                           const MachinePlan& plan) const override;
    // The templates on settings.paper (single sheet or tiles); std::invalid_argument names
    // the accepted papers for another value.
    std::string exportFileWith(const std::string& exportId, const Job& job, const MachinePlan& plan,
                               const ExportSettings& settings) const override;
    json::Value runReport(const Job& job, const MachinePlan& plan,
                          const TrackingReport& report) const override;
};

} // namespace cutcell
