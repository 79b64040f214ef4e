#include "ui/run_controller.h"
#include "ui/shown_number.h"

#include "ui/panels/engine_text.h"
#include "ui/panels/run_words.h"

#include "core/job/job_io.h"
#include "core/json/json.h"
#include "ui/forms/issue_text.h"
#include "ui/forms/job_editor.h"
#include "ui/link_control.h"
#include "ui/plan_worker.h"

#include "ui/machine/machine_ui_registry.h"

#include <QTimer>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace CutCell::ui {

using cutcell::EngineState;
using cutcell::Severity;

namespace {

// Parts of a job that shape the rig (devices, cycle, engine behaviour): a change rebuilds it.
std::string rigKey(const cutcell::Job& job) {
    const auto doc = cutcell::jobToJson(job);
    std::string key;
    for (const char* part :
         {"machine", "sim", "engine", "devices", "controller", "plant", "profile_cutter"})
        if (const auto* v = doc.find(part)) key += cutcell::json::write(*v, 0);
    return key;
}

bool busyState(EngineState s) {
    return s == EngineState::Running || s == EngineState::Paused || s == EngineState::Homing ||
           s == EngineState::Jogging || s == EngineState::EmergencyStop || s == EngineState::Fault;
}

} // namespace

RunController::RunController(JobEditor* editor, EngineRigFactory factory, QObject* parent)
    : QObject(parent), editor_(editor), factory_(std::move(factory)),
      planner_(new PlanWorker(this)), bridge_(new EngineBridge(this)),
      replanTimer_(new QTimer(this)), link_(new LinkControl(this)) {
    replanTimer_->setSingleShot(true);
    replanTimer_->setInterval(400); // replan after a pause in typing, not at every keystroke
    connect(replanTimer_, &QTimer::timeout, this, &RunController::replanNow);
    connect(editor_, &JobEditor::edited, this, [this] {
        replanTimer_->start();
        updateBlocked();
    });
    connect(editor_, &JobEditor::jobReset, this, &RunController::replanNow);
    connect(editor_, &JobEditor::jobReset, this, [this] { // a part counter per job
        parts_ = 0;
        lastCycleS_ = 0;
        coverage_.begin();
        setUnconfirmed({});
        emit countersChanged(parts_, lastCycleS_);
    });
    connect(planner_, &PlanWorker::started, this, [this] {
        emit planStarted();
        updateBlocked();
    });
    connect(planner_, &PlanWorker::progress, this, &RunController::planProgress);
    connect(planner_, &PlanWorker::planned, this, &RunController::onPlanned);
    connect(planner_, &PlanWorker::cancelled, this, [this] {
        // Superseded or invalid jobs cancel silently; only the operator's Cancel is logged.
        if (userCancelled_)
            emit message(Severity::Warning, tr("Planning cancelled by the operator."));
        userCancelled_ = false;
        updateBlocked();
    });
    connect(planner_, &PlanWorker::failed, this, [this](const QString& m) {
        emit message(Severity::Error, tr("Planning failed: %1").arg(m));
        updateBlocked();
    });
    connect(link_, &LinkControl::message, this, &RunController::message);
    connect(link_, &LinkControl::changed, this, &RunController::onLinkChanged);
    connect(link_, &LinkControl::enableDue, this, [this] {
        // The bus came up after Enable: enable now unless the machine left Idle meanwhile.
        if (rig_ && !estopPressed_ && bridge_->state() == EngineState::Idle)
            rig_->engine().enable();
    });
    connect(link_, &LinkControl::enableFailed, this, [this](const QString& why) {
        if (!autoRun_) return;
        autoRun_ = false;
        emit autoRunFinished(false, tr("the CAN bus did not come up: %1").arg(why));
    });
    connect(bridge_, &EngineBridge::stateChanged, this, &RunController::onState);
    connect(bridge_, &EngineBridge::samples, this, [this] {
        updateBlocked(); // e.g. homed may change within one tick without a visible state change
        if (autoRun_) stepAutoRun();
    });
    updateBlocked();
}

RunController::~RunController() {
    // The window's widgets that listen to the link may already be gone (children are deleted
    // before their parent's members): detach the rig without telling anyone.
    link_->blockSignals(true);
    link_->setRig(nullptr);
    bridge_->setEngine(nullptr);
    if (rig_) rig_->engine().emergencyStop(); // never leave a machine moving
    rig_.reset();
}

bool RunController::planning() const {
    return replanTimer_->isActive() || planner_->busy();
}

bool RunController::engineBusy() const {
    return busyState(bridge_->state());
}

void RunController::replanNow() {
    replanTimer_->stop();
    if (!editor_->valid()) {
        planner_->cancel();
        updateBlocked();
        if (autoRun_) {
            autoRun_ = false;
            emit autoRunFinished(false, blocked_);
        }
        return;
    }
    planner_->request(editor_->job());
    updateBlocked();
}

void RunController::cancelPlanning() {
    userCancelled_ = planner_->busy();
    replanTimer_->stop();
    planner_->cancel();
}

void RunController::onPlanned(std::shared_ptr<const cutcell::MachinePlan> plan,
                              const cutcell::Job& job) {
    plan_ = std::move(plan);
    planJob_ = job;
    programLoaded_ = false;
    programError_.clear();
    emit planChanged(plan_, planJob_);
    if (!plan_->ok()) {
        emit message(Severity::Error, tr("Path not reachable: %1").arg(planProblem()));
        updateBlocked();
        if (autoRun_) {
            autoRun_ = false;
            emit autoRunFinished(false, blocked_);
        }
        return;
    }
    if (const MachineUi* machine = machineUiFor(job))
        emit message(Severity::Info, machine->planSummary(job, *plan_));
    programPending_ = true;
    loadProgram();
}

void RunController::loadProgram() {
    if (!programPending_ || !plan_) return;
    if (engineBusy()) {
        updateBlocked(); // loaded when the engine is back at rest (onState)
        return;
    }
    programPending_ = false;
    if (!rig_ || rigKey(rigJob_) != rigKey(planJob_)) {
        link_->setRig(nullptr);
        bridge_->setEngine(nullptr);
        rig_.reset();
        std::string err;
        rig_ = factory_ ? factory_(planJob_, clock_, &err) : nullptr;
        if (!rig_) {
            programError_ = tr("machine not available: %1")
                                .arg(QString::fromStdString(err.empty() ? "no rig factory" : err));
            emit message(Severity::Error, programError_);
            rigDescription_.clear();
            emit rigChanged(tr("no machine: %1").arg(QString::fromStdString(err)));
            updateBlocked();
            return;
        }
        rigJob_ = planJob_;
        bridge_->setEngine(&rig_->engine());
        // In the GUI's language (ui/panels/engine_text.h): the rig writes it in English.
        rigDescription_ = engineText(QString::fromStdString(rig_->description()));
        emit rigChanged(rigDescription_);
        link_->setRig(rig_.get());
    }
    try {
        const MachineUi* machine = machineUiFor(planJob_);
        if (!machine) throw std::invalid_argument("no machine module for this job");
        const auto text = cutcell::json::write(cutcell::jobToJson(planJob_));
        auto program = programForRun(*plan_, text);
        if (!rig_->engine().load(program))
            throw std::runtime_error("the engine's command queue is full");
        programLoaded_ = true;
        program_ = std::move(program);
        programMachine_ = machine;
        emit programLoaded(program_);
    } catch (const std::exception& e) {
        programError_ = tr("cannot load the program: %1").arg(QString::fromUtf8(e.what()));
        emit message(Severity::Error, programError_);
    }
    updateBlocked();
    if (autoRun_) stepAutoRun();
}

void RunController::onState(EngineState s) {
    const EngineState was = lastState_;
    lastState_ = s;
    const bool wasCutting = was == EngineState::Running || was == EngineState::Paused;
    if (s == EngineState::Running && !wasCutting) emit runStarted();
    if (s == EngineState::Completed && wasCutting) {
        lastCycleS_ = bridge_->last().elapsed_s;
        if (countsUnits()) {
            // Pieces, strokes: what the run made, not one part per run.
            parts_ += static_cast<int>(bridge_->last().made);
        } else if (coverage_.whole()) {
            ++parts_;
        } else {
            setUnconfirmed(describeGaps());
            emit message(Severity::Warning,
                         tr("Part not counted as good: %1. Confirm it in the recovery box if it "
                            "was finished otherwise.")
                             .arg(unconfirmed_));
        }
        emit countersChanged(parts_, lastCycleS_);
    }
    const bool stopped =
        ((s == EngineState::EmergencyStop || s == EngineState::Fault) && was != s && wasCutting) ||
        (s == EngineState::Ready && wasCutting);
    if (s == EngineState::EmergencyStop && was != s)
        emit runStopped(s, tr("emergency stop"));
    else if (s == EngineState::Fault && was != s)
        emit runStopped(s, tr("fault"));
    else if (s == EngineState::Ready && wasCutting)
        emit runStopped(s, tr("abort"));
    if (stopped) fetchStopPoint(0);
    if (s == EngineState::Ready && wasCutting) homeAfterAbort_ = true;
    if (s == EngineState::Homing) homeAfterAbort_ = false;
    if (s != EngineState::Jogging) jogging_ = false;
    if (programPending_ && !busyState(s)) loadProgram();
    updateBlocked();
    if (autoRun_) stepAutoRun();
}

QString RunController::planProblem() const {
    const QString text = engineText(QString::fromStdString(plan_->outcome.message));
    return labelKeys_ ? labelKeys_(text) : text;
}

void RunController::updateBlocked() {
    QString r;
    const auto s = bridge_->state();
    const auto& issues = editor_->issues();
    if (!issues.empty())
        r = tr("%n invalid field(s) - %1", nullptr, static_cast<int>(issues.size()))
                .arg(describeIssue_ ? describeIssue_(issues.front())
                                    : issueText(issues.front(), QString()));
    else if (planning())
        r = tr("planning the path...");
    else if (!plan_)
        r = tr("no plan yet");
    else if (!plan_->ok())
        r = tr("path not reachable - %1").arg(planProblem());
    else if (!programError_.isEmpty())
        r = programError_;
    else if (programPending_ && busyState(s))
        r = tr("the new plan is loaded when the machine is at rest");
    else if (!programLoaded_)
        r = tr("no program loaded");
    else {
        switch (s) {
        case EngineState::Idle:
            r = link_->ready() ? tr("drives disabled - press Enable") : linkBlockedReason();
            break;
        case EngineState::Ready:
            if (!bridge_->last().homed)
                r = tr("axes not homed - press Home");
            else if (homeAfterAbort_)
                r = abortedReason();
            break;
        case EngineState::Homing:
            r = tr("homing in progress");
            break;
        case EngineState::Jogging:
            r = tr("jogging in progress");
            break;
        case EngineState::Running:
            r = tr("the cut is running");
            break;
        case EngineState::Paused:
            r = tr("feed hold - press Resume or Abort");
            break;
        case EngineState::Completed:
            r = tr("cut completed - press Home to cut again");
            break;
        case EngineState::EmergencyStop:
            r = estopPressed_ ? tr("EMERGENCY STOP pressed - release it, then press Reset")
                              : tr("EMERGENCY STOP latched - press Reset");
            break;
        case EngineState::Fault:
            r = link_->needsReconnect()
                    ? tr("fault - CAN bus %1: press Reset (it reconnects the bus), then Enable")
                          .arg(QString::fromLatin1(toString(link_->link().state)))
                    : tr("fault - see the event log, then press Reset");
            break;
        }
    }
    // The log-in (the run gate) comes after what the machine says while it moves or is
    // stopped: an E-STOP, a fault, a running cut or a feed hold keep their own words.
    const bool atRest =
        s == EngineState::Idle || s == EngineState::Ready || s == EngineState::Completed;
    if (const QString gate = runGate_ ? runGate_() : QString(); !gate.isEmpty() && atRest) r = gate;
    if (r != blocked_) {
        blocked_ = r;
        emit startBlockedChanged(blocked_);
    }
}

QString RunController::abortedReason() const {
    return tr("run aborted - press Home to cut again (or resume in the cut recovery box)");
}

QString RunController::linkBlockedReason() const {
    const RigLink& l = link_->link();
    const QString text = engineText(QString::fromStdString(l.text));
    switch (l.state) {
    case RigLink::State::Down:
        return tr("drives disabled, CAN bus not connected - press Enable (it connects the bus)");
    case RigLink::State::Connecting:
        return link_->enablePending()
                   ? tr("connecting the CAN bus - %1; the drives are enabled when every node "
                        "is up")
                         .arg(text)
                   : tr("connecting the CAN bus - %1").arg(text);
    case RigLink::State::Failed:
        return tr("CAN bus not up - %1 - press Enable to try again").arg(text);
    case RigLink::State::Lost:
        return tr("CAN bus lost - %1 - press Reconnect or Reset, then Enable").arg(text);
    default:
        return {};
    }
}

void RunController::onLinkChanged(const RigLink& link) {
    if (!rigDescription_.isEmpty() && link.state != RigLink::State::None)
        emit rigChanged(
            tr("%1 - bus %2").arg(rigDescription_, QString::fromLatin1(toString(link.state))));
    updateBlocked();
    emit linkChanged(link);
}

void RunController::enable() {
    if (rig_ && link_->requestEnable()) rig_->engine().enable();
}

void RunController::reconnect() {
    if (!rig_) return;
    const EngineState s = bridge_->state();
    if (s != EngineState::Idle && s != EngineState::Fault && s != EngineState::EmergencyStop) {
        emit message(Severity::Warning,
                     tr("Reconnect refused: the drives are enabled (%1); a reconnection takes "
                        "their torque away. Abort or stop first.")
                         .arg(stateWord(s)));
        return;
    }
    link_->reconnect();
}
void RunController::home() {
    if (rig_) rig_->engine().home();
}
void RunController::start() {
    if (!rig_ || !blocked_.isEmpty()) return;
    emit runStarting();
    coverage_.begin();
    setUnconfirmed({});
    rig_->engine().start();
}
void RunController::startFrom(double pathTime_s) {
    // A recovery continues the aborted cut from where the axes are: no Home needed for it.
    const bool onlyAborted = homeAfterAbort_ && blocked_ == abortedReason();
    if (!rig_ || (!blocked_.isEmpty() && !onlyAborted)) return;
    homeAfterAbort_ = false;
    emit runStarting();
    emit recoveryStarting(pathTime_s);
    coverage_.recoverFrom(pathTime_s);
    setUnconfirmed({});
    rig_->engine().startFrom(pathTime_s);
}

void RunController::confirmPart() {
    if (unconfirmed_.isEmpty()) return;
    ++parts_;
    emit message(Severity::Info,
                 tr("Part counted as good by the operator (%1).").arg(unconfirmed_));
    coverage_.begin();
    setUnconfirmed({});
    emit countersChanged(parts_, lastCycleS_);
}

void RunController::setUnconfirmed(const QString& text) {
    if (text == unconfirmed_) return;
    unconfirmed_ = text;
    emit unconfirmedPartChanged(unconfirmed_);
}

QString RunController::describeGaps() const {
    QStringList parts;
    const double dt = program_ && program_->spline.dt() > 0 ? program_->spline.dt() : 0;
    const double T = program_ ? program_->cut_time_s : 0;
    for (const PartCoverage::Gap& g : coverage_.gaps()) {
        if (dt <= 0 || T <= 0) {
            parts << tr("path time %1 to %2 s not cut")
                         .arg(shownNumber(g.from_s, 3))
                         .arg(shownNumber(g.to_s, 3));
            continue;
        }
        // Points shown 1-based as the progress panel does; mm in the recovery's own measure.
        parts << tr("points %1 to %2 (%3 mm) never cut")
                     .arg(static_cast<long>(g.from_s / dt) + 1)
                     .arg(static_cast<long>(g.to_s / dt) + 1)
                     .arg(shownNumber((g.to_s - g.from_s) / T * program_->length_mm, 1));
    }
    return parts.join(QStringLiteral("; "));
}

void RunController::fetchStopPoint(int attempt) {
    // The engine publishes the run's result in the cycle it stops; the state may be seen first.
    if (!rig_) return;
    cutcell::TrackingReport report;
    cutcell::RunStopPoint stop;
    if (rig_->engine().lastRunReport(report, nullptr, &stop) && stop.valid) {
        coverage_.stoppedAt(stop.path_time_s);
        if (countsUnits() && stop.made > 0) { // the pieces or strokes made before the stop
            parts_ += static_cast<int>(stop.made);
            emit countersChanged(parts_, lastCycleS_);
        }
        emit stopPointChanged(stop);
        return;
    }
    if (attempt < 10)
        QTimer::singleShot(50, this, [this, attempt] { fetchStopPoint(attempt + 1); });
}
void RunController::feedHold() {
    if (rig_) rig_->engine().feedHold();
}
void RunController::resume() {
    if (rig_) rig_->engine().resume();
}
void RunController::abort() {
    if (rig_) rig_->engine().abort();
}
void RunController::setOverride(double fraction) {
    if (rig_) rig_->engine().setOverride(fraction);
}

void RunController::reset() {
    if (!rig_) return;
    if (estopPressed_) {
        emit message(Severity::Warning,
                     tr("Reset refused: the EMERGENCY STOP is still pressed (Release E-STOP "
                        "first)."));
        return;
    }
    const EngineState s = bridge_->state();
    const bool latched = s == EngineState::Fault || s == EngineState::EmergencyStop;
    if (link_->needsReconnect()) {
        // A lost or failed bus: the drives' faults cannot clear without it. Reset clears the
        // latch and reconnects; Enable follows by the operator once the bus is up.
        if (latched) rig_->engine().reset();
        emit message(Severity::Info, tr("Reset: reconnecting the CAN bus; press Enable when it "
                                        "is up (the bus box shows it)."));
        link_->reconnect();
        return;
    }
    rig_->engine().reset();
}

void RunController::emergencyStop() {
    emit message(Severity::Error, tr("EMERGENCY STOP pressed by the operator."));
    if (rig_) rig_->engine().emergencyStop();
    link_->cancelEnable(); // a bus coming up now enables nothing
    if (!estopPressed_) {
        estopPressed_ = true;
        emit eStopPressedChanged(true);
        updateBlocked();
    }
}

void RunController::releaseEmergencyStop() {
    if (!estopPressed_) return;
    // The operator has pulled the mushroom button back out; Reset is a second, separate step.
    if (rig_) rig_->engine().releaseEmergencyStop();
    estopPressed_ = false;
    emit message(Severity::Info, tr("EMERGENCY STOP released: press Reset to clear the latch."));
    emit eStopPressedChanged(false);
    updateBlocked();
}

void RunController::jog(int axis, double delta) {
    if (rig_) rig_->engine().jog(axis, delta);
}

void RunController::jogContinuous(int axis, int direction) {
    if (!rig_ || !program_ || axis < 0 || axis >= program_->axis_count || direction == 0) return;
    const auto& last = bridge_->last();
    const double at = last.setpoint[axis];
    // Toward the axis limit, at most one turn (rotary) or a metre (linear) per press; the
    // release stops the move (stopJog) along its ramp.
    const double reach =
        program_->axis_linear[static_cast<size_t>(axis)] ? 1000.0 : 2 * std::numbers::pi;
    const double limit =
        direction > 0 ? program_->max_position[axis] : program_->min_position[axis];
    const double delta = direction > 0 ? std::min(reach, limit - at) : std::max(-reach, limit - at);
    if (std::abs(delta) < 1e-9) {
        emit message(Severity::Warning, tr("Jog refused: axis %1 is at its limit.").arg(axis));
        return;
    }
    jogging_ = rig_->engine().jog(axis, delta);
}

void RunController::stopJog() {
    if (rig_ && jogging_) rig_->engine().abort();
    jogging_ = false;
}

void RunController::startAutoRun() {
    autoRun_ = true;
    autoEnableSent_ = autoHomeSent_ = autoStartSent_ = false;
    stepAutoRun();
}

void RunController::stepAutoRun() {
    if (!autoRun_ || !rig_ || !programLoaded_) return;
    const auto s = bridge_->state();
    auto& engine = rig_->engine();
    const auto finish = [this](bool ok, const QString& why) {
        autoRun_ = false;
        emit autoRunFinished(ok, why);
    };
    // An unattended run (--run) asks the same gate as the Start button: with users, nobody is
    // logged in at the start, so it is refused rather than run by no one.
    const QString gate = runGate_ && !autoStartSent_ ? runGate_() : QString();
    if (!gate.isEmpty()) {
        finish(false, gate);
        return;
    }
    switch (s) {
    case EngineState::Idle:
        if (!autoEnableSent_) {
            autoEnableSent_ = true;
            if (link_->requestEnable()) autoEnableSent_ = engine.enable();
        }
        break;
    case EngineState::Ready:
        if (!bridge_->last().homed) {
            if (!autoHomeSent_) autoHomeSent_ = engine.home();
        } else if (!autoStartSent_) {
            emit runStarting();
            autoStartSent_ = engine.start();
        }
        break;
    case EngineState::Completed:
        if (autoStartSent_) finish(true, {});
        break;
    case EngineState::EmergencyStop:
        finish(false, tr("emergency stop during the run"));
        break;
    case EngineState::Fault:
        finish(false, tr("fault during the run (see the event log)"));
        break;
    default:
        break;
    }
}

bool RunController::countsUnits() const {
    return program_ && program_->terms.counts != cutcell::WorkCount::PathPoints;
}

} // namespace CutCell::ui
