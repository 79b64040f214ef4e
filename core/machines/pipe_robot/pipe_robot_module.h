#pragma once
// The pipe-cutting robot of seed 000: a pipe chuck (axis 0) and a 5-DOF arm (axes 1..5), all
// rotary, torque-controlled joints behind PID drives; CANopen drives or simulated ones.
//
// Its `machine` section: the pipe joint (main_pipe, branch_pipe, angle_deg, eccentricity_mm,
// cut), method ("static_pipe" | "rotating_pipe"), robot.dh[6], controller[6], plant[6].
#include "core/machine/machine_module.h"
#include "core/machines/pipe_robot/cut_planner.h"

namespace cutcell {

inline constexpr const char* kPipeRobotId = "pipe_robot_6axis";

// MachinePlan::data of its plans is the CutPlan.
class PipeRobotModule : public MachineModule {
  public:
    std::string id() const override { return kPipeRobotId; }
    std::string title() const override { return "Pipe-cutting robot (chuck + 5-DOF arm)"; }
    std::vector<AxisInfo> axes(const Job& job) const override;
    Job defaultJob() const override;
    void readSection(const json::Value& section, Job& job) const override;
    json::Value writeSection(const Job& job) const override;
    void migrateSchema1(json::Object& section) const override;
    std::vector<JobIssue> validate(const Job& job) const override;
    Outcome canOpen() const override { return Outcome::done(); }
    // The arm (DH table, axis ranges), its joints' PID gains and plant; pipes, method and cut
    // are the setter's.
    bool isMachineParameter(const std::string& key) const override;
    MachinePlan plan(const Job& job, const std::string& jobText,
                     const PlanOptions& options) const override;
    Outcome setVariant(Job& job, const std::string& variant) const override;
    // Both methods, static and rotating pipe (method_comparison.cpp, seed 000 Fig. 11-14).
    Outcome compareMethods(const Job& job, MethodComparisonFiles* out) const override;
    std::vector<ExportInfo> exports() const override;
    std::string exportFile(const std::string& exportId, const Job& job,
                           const MachinePlan& plan) const override;
    Outcome offlineReport(const Job& job, const MachinePlan& plan, std::string* json,
                          std::string* text) const override;
    json::Value runReport(const Job& job, const MachinePlan& plan,
                          const TrackingReport& report) const override;
    // ik_ns_per_solve, simulate_seconds, simulated_seconds, simulate_realtime_factor,
    // simulate_realtime_factor_rigid_body, simulate_realtime_factor_linear, forward_dynamics_us.
    void addBenchFigures(bool quick, json::Object& out) const override;
    // Arm "arm": theta1..theta5 (deg, optionally theta0 first) -> torch; a pose -> every branch.
    Outcome forwardKinematics(const Job& job, const std::string& arm,
                              const std::vector<double>& jointsDeg,
                              json::Value* out) const override;
    Outcome inverseKinematics(const Job& job, const std::string& arm,
                              const std::vector<double>& pose, json::Value* out) const override;
    // SIMC gains for the six PID drives (pipe_robot_tuning.h; defined in pipe_robot_tuning.cpp).
    Outcome tuneControllers(Job& job, const TuneOptions& options, std::string* text) const override;
};

} // namespace cutcell
