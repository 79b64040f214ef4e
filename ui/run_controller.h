#pragma once
// Coordinates a run: job edits -> planning off the GUI thread -> motion program -> engine rig
// (built by the composition root's factory) -> operator commands. It decides whether Start is
// allowed and says why not (invalid fields, planning, unreachable path, engine state), and
// can drive a whole run by itself (Enable, Home, Start) for `cutcell --run`.
//
// Threading contract: GUI thread only; nothing here waits on the engine or the planner.
#include "core/job/job.h"
#include "core/job/job_io.h"
#include "core/machine/machine_module.h"
#include "ui/engine_bridge.h"
#include "ui/engine_rig.h"
#include "ui/part_coverage.h"

#include <QObject>

#include <functional>
#include <memory>

class QTimer;

namespace CutCell::ui {

class JobEditor;
class LinkControl;
class MachineUi;
class PlanWorker;

class RunController : public QObject {
    Q_OBJECT
  public:
    RunController(JobEditor* editor, EngineRigFactory factory, QObject* parent = nullptr);
    ~RunController() override;

    void setClockMode(cutcell::ClockMode clock) { clock_ = clock; }
    // How an invalid field is named in the Start reason (the forms know the labels).
    void setIssueDescriber(std::function<QString(const cutcell::JobIssue&)> describe) {
        describeIssue_ = std::move(describe);
    }
    // How a planner's refusal names the job's keys (the forms know the labels).
    void setKeyLabeller(std::function<QString(const QString&)> labelled) {
        labelKeys_ = std::move(labelled);
    }
    EngineBridge* bridge() const { return bridge_; }
    PlanWorker* planner() const { return planner_; }
    std::shared_ptr<const cutcell::MachinePlan> plan() const { return plan_; }
    QString startBlockedReason() const { return blocked_; }
    // What else blocks Start ("" for nothing): the station's log-in (app wiring). Call
    // recheckStart() when its answer changes.
    void setRunGate(std::function<QString()> gate) {
        runGate_ = std::move(gate);
        recheckStart();
    }
    void recheckStart() { updateBlocked(); }
    bool planning() const;
    EngineRig* rig() const { return rig_.get(); } // null until a plan was loaded
    // The rig's link to its drives (a CAN bus): its state, Enable's wait for it.
    LinkControl* link() const { return link_; }
    // Plans the current job now (after an open or a New; edits replan after a short pause).
    void replanNow();

    // The program the engine runs (null before the first load): axis names, units, limits.
    std::shared_ptr<const cutcell::MotionProgram> program() const { return program_; }
    // The machine UI of the loaded program (null before the first load): axis labels.
    const MachineUi* programMachine() const { return programMachine_; }
    // Whether the emergency stop request is pressed (until releaseEmergencyStop()).
    bool eStopPressed() const { return estopPressed_; }
    // What was made since this job was opened: for a path machine the runs that reached
    // Completed over their whole path, for a machine that counts pieces or strokes
    // (MotionProgram::terms) the pieces or strokes of every run, stopped ones too; and the last
    // completed run's cycle time (Start to Completed, s; 0 before the first).
    int partsCompleted() const { return parts_; }
    double lastCycleS() const { return lastCycleS_; }
    // A run completed a part whose path has stretches no run cut (Run from point beyond the
    // stop): the part is not counted until the operator confirms it. Empty if none waits.
    QString unconfirmedPart() const { return unconfirmed_; }
    // The operator confirms the waiting part as good (it was finished otherwise): counted.
    void confirmPart();

    // Operator commands (non-blocking requests to the engine).
    void enable();
    void home();
    void start();
    // Cut recovery: the rest of the cut from this path time (s) of the loaded program.
    void startFrom(double pathTime_s);
    void feedHold();
    void resume();
    void abort();
    // Clears a fault, or an emergency stop that was released; after a lost or failed bus it
    // also reconnects the bus (Enable follows by the operator).
    void reset();
    // Takes the bus down and up again (bus box); refused while the drives are enabled.
    void reconnect();
    void emergencyStop();
    void releaseEmergencyStop();
    // Jog one axis while Ready: by `delta` (rad or mm), or continuously toward `direction`
    // (+1/-1, up to the axis limit) until stopJog().
    void jog(int axis, double delta);
    void jogContinuous(int axis, int direction);
    void stopJog();
    void setOverride(double fraction);
    void cancelPlanning();

    // Enable, Home and Start by itself as soon as the plan is loaded; finishes with
    // autoRunFinished(true) at Completed, (false, reason) on a fault or emergency stop.
    void startAutoRun();

  signals:
    void planStarted();
    void planProgress(double fraction);
    void planChanged(std::shared_ptr<const cutcell::MachinePlan> plan, const cutcell::Job& job);
    void startBlockedChanged(const QString& reason);
    void message(cutcell::Severity severity, const QString& text);
    void rigChanged(const QString& description);
    void linkChanged(const CutCell::ui::RigLink& link);
    void autoRunFinished(bool ok, const QString& reason);
    void programLoaded(std::shared_ptr<const cutcell::MotionProgram> program);
    void eStopPressedChanged(bool pressed);
    // Start is being sent (button, key or auto run): the previous run's data can go now (a
    // fast run may be over before its first state change is seen).
    void runStarting();
    // A cut recovery was accepted and starts from this path time (startFrom passed its checks).
    void recoveryStarting(double pathTime_s);
    // A cut began (Ready -> Running) / ended short of its end (emergency stop, fault, abort).
    void runStarted();
    void runStopped(cutcell::EngineState state, const QString& how);
    // Where the run that ended short stopped (the engine's stop point, for cut recovery).
    void stopPointChanged(const cutcell::RunStopPoint& stop);
    void countersChanged(int parts, double lastCycleS);
    // A part waits for the operator's confirmation (text: what was not cut), or no longer
    // (empty).
    void unconfirmedPartChanged(const QString& text);

  private:
    // The plan's refusal in the GUI's language, its keys named by the fields' labels.
    QString planProblem() const;
    void onPlanned(std::shared_ptr<const cutcell::MachinePlan> plan, const cutcell::Job& job);
    void loadProgram();
    void onState(cutcell::EngineState state);
    void stepAutoRun();
    void fetchStopPoint(int attempt);
    void updateBlocked();
    QString linkBlockedReason() const;
    QString abortedReason() const;
    void onLinkChanged(const RigLink& link);
    bool rigMatches(const cutcell::Job& job) const;
    bool engineBusy() const;
    bool countsUnits() const; // the program counts pieces or strokes, not whole parts

    JobEditor* editor_;
    EngineRigFactory factory_;
    PlanWorker* planner_;
    EngineBridge* bridge_;
    QTimer* replanTimer_;
    cutcell::ClockMode clock_ = cutcell::ClockMode::RealTime;
    LinkControl* link_;
    std::unique_ptr<EngineRig> rig_;
    QString rigDescription_;
    cutcell::Job rigJob_;
    std::shared_ptr<const cutcell::MachinePlan> plan_;
    cutcell::Job planJob_;
    bool programPending_ = false;
    bool programLoaded_ = false;
    QString programError_;
    QString blocked_;
    std::function<QString()> runGate_;
    std::shared_ptr<const cutcell::MotionProgram> program_;
    const MachineUi* programMachine_ = nullptr;
    cutcell::EngineState lastState_ = cutcell::EngineState::Idle;
    bool estopPressed_ = false;
    // An abort left the axes somewhere on the path: a new cut starts from Home (as after a
    // completed one); the cut recovery may still resume from there.
    bool homeAfterAbort_ = false;
    bool jogging_ = false;
    int parts_ = 0;
    double lastCycleS_ = 0;
    PartCoverage coverage_;
    QString unconfirmed_;
    void setUnconfirmed(const QString& text);
    QString describeGaps() const;
    bool autoRun_ = false;
    bool userCancelled_ = false;
    bool autoEnableSent_ = false, autoHomeSent_ = false, autoStartSent_ = false;
    std::function<QString(const cutcell::JobIssue&)> describeIssue_;
    std::function<QString(const QString&)> labelKeys_;
};

} // namespace CutCell::ui
