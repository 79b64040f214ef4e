#pragma once
// The profile-milling flying saw of seed 003 at the end of a welded-pipe line: a carriage
// (linear, CSP) synchronised to the line measured by a roller encoder, a turntable (rotary)
// carrying two saw blades with radial feeds (linear) on cam tables of the turntable angle.
//
// Its `machine` section: tube { shape, diameter_mm | width_mm, height_mm, corner_radius_mm,
// wall_mm }, line { speed_m_min, roller_pulses_per_rev, roller_diameter_mm, filter_alpha },
// cut { queue[] { length_mm, count }, tolerance_mm, first_sync_master_mm }, carriage {...},
// saw {...}, blade {...}, gauge {...}, line_sim {...} (README, "Flying saw").
#include "core/machine/machine_module.h"
#include "core/machines/flying_saw/flying_saw_plan.h"
#include "core/machines/flying_saw/flying_saw_spec.h"

namespace cutcell {

inline constexpr const char* kFlyingSawId = "flying_saw";

// MachinePlan::data of the flying saw's plans.
struct FlyingSawPlanData {
    FlyingSawSpec spec;
    FlyingSawPlan plan;
};

class FlyingSawModule : public MachineModule {
  public:
    std::string id() const override { return kFlyingSawId; }
    std::string title() const override {
        return "Flying saw on a welded-pipe line (carriage + turntable + 2 feeds)";
    }
    std::vector<AxisInfo> axes(const Job& job) const override;
    Job defaultJob() const override;
    void readSection(const json::Value& section, Job& job) const override;
    json::Value writeSection(const Job& job) const override;
    void migrateSchema1(json::Object& section) const override;
    std::vector<JobIssue> validate(const Job& job) const override;
    Outcome canOpen() const override;
    std::vector<std::string> sensorNames() const override { return {"line encoder"}; }
    RunTerms runTerms() const override;
    // The line's encoder and filter, the carriage, the saw's turntable and the gauge; the
    // feeds, the overcut and the blade are the setter's.
    bool isMachineParameter(const std::string& key) const override;
    MachinePlan plan(const Job& job, const std::string& jobText,
                     const PlanOptions& options) const override;
    std::vector<ExportInfo> exports() const override;
    std::string exportFile(const std::string& exportId, const Job& job,
                           const MachinePlan& plan) const override;
    Outcome offlineReport(const Job& job, const MachinePlan& plan, std::string* json,
                          std::string* text) const override;
    // 200 pieces of 6 m at 60 m/min, line +-2 % at 0.1 Hz with +-1 % steps, 0.05 mm encoder.
    void addBenchFigures(bool quick, json::Object& out) const override;
    json::Value runReport(const Job& job, const MachinePlan& plan,
                          const TrackingReport& report) const override;
};

// The job's flying-saw section (throws JobError when the job holds another machine's).
const FlyingSawSpec& flyingSawSpec(const Job& job);

} // namespace cutcell
