#pragma once
// Coordinates a run: job edits -> planning off the GUI thread -> motion program -> engine rig
// (built by the composition root's factory) -> operator commands. It decides whether Start is
// allowed and says why not (invalid fields, planning, unreachable path, engine state), and
// can drive a whole run by itself (Enable, Home, Start) for `cutcell --run`.
//
// Threading contract: GUI thread only; nothing here waits on the engine or the planner.
#include "core/job/job.h"
#include "core/trajectory/cut_planner.h"
#include "ui/engine_bridge.h"
#include "ui/engine_rig.h"

#include <QObject>

#include <memory>

class QTimer;

namespace CutCell::ui {

class JobEditor;
class PlanWorker;

class RunController : public QObject {
    Q_OBJECT
  public:
    RunController(JobEditor* editor, EngineRigFactory factory, QObject* parent = nullptr);
    ~RunController() override;

    void setClockMode(cutcell::ClockMode clock) { clock_ = clock; }
    EngineBridge* bridge() const { return bridge_; }
    PlanWorker* planner() const { return planner_; }
    std::shared_ptr<const cutcell::CutPlan> plan() const { return plan_; }
    QString startBlockedReason() const { return blocked_; }
    bool planning() const;
    EngineRig* rig() const { return rig_.get(); } // null until a plan was loaded
    // Plans the current job now (after an open or a New; edits replan after a short pause).
    void replanNow();

    // Operator commands (non-blocking requests to the engine).
    void enable();
    void home();
    void start();
    void feedHold();
    void resume();
    void abort();
    void reset();
    void emergencyStop();
    void setOverride(double fraction);
    void cancelPlanning();

    // Enable, Home and Start by itself as soon as the plan is loaded; finishes with
    // autoRunFinished(true) at Completed, (false, reason) on a fault or emergency stop.
    void startAutoRun();

  signals:
    void planStarted();
    void planProgress(double fraction);
    void planChanged(std::shared_ptr<const cutcell::CutPlan> plan, const cutcell::Job& job);
    void startBlockedChanged(const QString& reason);
    void message(cutcell::Severity severity, const QString& text);
    void rigChanged(const QString& description);
    void autoRunFinished(bool ok, const QString& reason);

  private:
    void onPlanned(std::shared_ptr<const cutcell::CutPlan> plan, const cutcell::Job& job);
    void loadProgram();
    void onState(cutcell::EngineState state);
    void stepAutoRun();
    void updateBlocked();
    bool rigMatches(const cutcell::Job& job) const;
    bool engineBusy() const;

    JobEditor* editor_;
    EngineRigFactory factory_;
    PlanWorker* planner_;
    EngineBridge* bridge_;
    QTimer* replanTimer_;
    cutcell::ClockMode clock_ = cutcell::ClockMode::RealTime;
    std::unique_ptr<EngineRig> rig_;
    cutcell::Job rigJob_;
    std::shared_ptr<const cutcell::CutPlan> plan_;
    cutcell::Job planJob_;
    bool programPending_ = false;
    bool programLoaded_ = false;
    QString programError_;
    QString blocked_;
    bool autoRun_ = false;
    bool userCancelled_ = false;
    bool autoEnableSent_ = false, autoHomeSent_ = false, autoStartSent_ = false;
};

} // namespace CutCell::ui
