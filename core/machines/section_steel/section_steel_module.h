#pragma once
// The section-steel cutting cell of seed 001: a 3R cutting-path arm (axes 0..2) and a 5-DOF
// groove arm (axes 3..7), all rotary, position-commanded (CSP) joints behind PID drives; the
// program is a joint spline (MotionSourceKind::JointSpline). Its `machine` section: section
// (designation or dimensions), the optional process (core/process/process_spec.h: the cut chart
// entry and overrides, read as the pipe machines read it; it gives the kerf, compensated by the
// plan: section_kerf.h), end_cut (mitres, grooves of flanges and web), motion, path_arm,
// groove_arm, park_deg[8], drives[8]. See README "Section-steel cutter".
#include "core/machine/machine_module.h"

namespace cutcell {

inline constexpr const char* kSectionSteelId = "section_steel_cutter";

// MachinePlan::data of its plans is the section_steel::SteelPlan.
class SectionSteelModule : public MachineModule {
  public:
    std::string id() const override { return kSectionSteelId; }
    std::string title() const override {
        return "Section-steel cutter (3R path arm + 5-DOF groove arm)";
    }
    std::vector<AxisInfo> axes(const Job& job) const override;
    Job defaultJob() const override;
    void readSection(const json::Value& section, Job& job) const override;
    json::Value writeSection(const Job& job) const override;
    void migrateSchema1(json::Object&) const override {}
    std::vector<JobIssue> validate(const Job& job) const override;
    Outcome canOpen() const override;
    // The two arms, the torch's size and lean, the park pose and the drives; the section, the
    // end cut and the speeds are the setter's.
    bool isMachineParameter(const std::string& key) const override;
    MachinePlan plan(const Job& job, const std::string& jobText,
                     const PlanOptions& options) const override;
    std::vector<ExportInfo> exports() const override;
    std::string exportFile(const std::string& exportId, const Job& job,
                           const MachinePlan& plan) const override;
    // section_ik_ns_per_solve, section_torch_ik_ns_per_solve, section_end_cut_plan_ms.
    void addBenchFigures(bool quick, json::Object& out) const override;
    // "dstv": DSTV (NC1) pieces (dstv/dstv_import.h).
    std::vector<JobImporter> importers() const override;
    json::Value runReport(const Job& job, const MachinePlan& plan,
                          const TrackingReport& report) const override;
    // Arms "path" and "groove" (section_steel_kinematics_json.cpp).
    Outcome forwardKinematics(const Job& job, const std::string& arm,
                              const std::vector<double>& jointsDeg,
                              json::Value* out) const override;
    Outcome inverseKinematics(const Job& job, const std::string& arm,
                              const std::vector<double>& pose, json::Value* out) const override;
};

} // namespace cutcell
