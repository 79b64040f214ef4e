#pragma once
// The quick-return (inverted Whitworth) cutter of seed 004: one crank in torque mode run by a
// task-space control law on the slider's linear scale (quick_return_law.h). Job section:
// quick_return_spec.h. `cutcell-cli simulate` runs both experiments offline for the four
// controllers (experiments.h), and for a job of experiment 1 ("tracking") its study
// (paper_parameters.h: limit cycles, the OSMC's k2 sweep); `cutcell-cli run` runs the job's
// experiment and controller in the engine on the simulated mechanism
// (devices/machines/quick_return/quick_return_sim_rig.cpp).
#include "core/machine/machine_module.h"
#include "core/machines/quick_return/paper_parameters.h"
#include "core/machines/quick_return/quick_return_spec.h"

namespace cutcell {

// MachinePlan::data of the quick-return cutter's plans.
struct QuickReturnPlanData {
    quick_return::ExperimentSetup setup;
};

// Both experiments for all four controllers as the report's JSON and a text table.
json::Value quickReturnReport(const QuickReturnSpec& spec, const quick_return::ExperimentSetup& s,
                              std::string* table);

// The experiment-1 study (paper_parameters.h) as lines for the terminal and as JSON.
std::string experiment1StudyText(const quick_return::Experiment1Study& st,
                                 const quick_return::ExperimentSetup& s);
json::Value experiment1StudyJson(const quick_return::Experiment1Study& st,
                                 const quick_return::ExperimentSetup& s);

class QuickReturnModule : public MachineModule {
  public:
    std::string id() const override { return kQuickReturnId; }
    std::string title() const override {
        return "Quick-return (Whitworth) cutter, crank in torque mode";
    }
    std::vector<AxisInfo> axes(const Job& job) const override;
    Job defaultJob() const override;
    void readSection(const json::Value& section, Job& job) const override;
    json::Value writeSection(const Job& job) const override;
    void migrateSchema1(json::Object& section) const override;
    std::vector<JobIssue> validate(const Job& job) const override;
    Outcome canOpen() const override;
    std::vector<std::string> sensorNames() const override { return {"slider scale"}; }
    RunTerms runTerms() const override;
    // The mechanism, the slider, the crank's motor and the control law with its gains; the cut
    // and the tracking test are the setter's.
    bool isMachineParameter(const std::string& key) const override;
    MachinePlan plan(const Job& job, const std::string& jobText,
                     const PlanOptions& options) const override;
    std::vector<ExportInfo> exports() const override;
    std::string exportFile(const std::string& exportId, const Job& job,
                           const MachinePlan& plan) const override;
    Outcome offlineReport(const Job& job, const MachinePlan& plan, std::string* json,
                          std::string* text) const override;
    json::Value runReport(const Job& job, const MachinePlan& plan,
                          const TrackingReport& report) const override;
    // Experiment 1 MSE and experiment 2 velocity error of every controller (default job).
    void addBenchFigures(bool quick, json::Object& out) const override;

    // simulate's work: at most this many samples over both experiments and all controllers
    // (the shipped job: about 5.5e4; at a sample time of 1e-5 s 5.5e6, with 1000 strokes 5e6).
    static constexpr double kMaxOfflineSamples = 2e6;
    // "" when simulate's work is within the bound, else the refusal with the estimate.
    static std::string offlineWorkProblem(const QuickReturnSpec& spec,
                                          const quick_return::ExperimentSetup& s);
};

} // namespace cutcell
