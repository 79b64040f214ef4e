// Every command in every state: the new state, or a refusal event with its reason.
#include "engine_fixture.h"

#include <functional>

namespace cutcell::test {
namespace {

enum class From {
    Idle,
    ReadyUnhomed,
    ReadyHomed,
    Homing,
    Jogging,
    Running,
    Paused,
    Completed,
    EStop,
    Fault
};

const char* name(From f) {
    static const char* names[] = {"Idle",    "ReadyUnhomed", "ReadyHomed", "Homing", "Jogging",
                                  "Running", "Paused",       "Completed",  "EStop",  "Fault"};
    return names[static_cast<int>(f)];
}

void bringTo(SimCell& c, From f) {
    switch (f) {
    case From::Idle:
        return;
    case From::ReadyUnhomed:
        return c.toReady(false);
    case From::ReadyHomed:
        return c.toReady(true);
    case From::Homing:
        return c.toHoming();
    case From::Jogging:
        return c.toJogging();
    case From::Running:
        return c.toRunning();
    case From::Paused:
        return c.toPaused();
    case From::Completed:
        return c.toCompleted();
    case From::EStop:
        return c.toEmergencyStop();
    case From::Fault:
        return c.toFault();
    }
}

enum class Cmd {
    Load,
    Enable,
    Disable,
    Home,
    Jog,
    Start,
    FeedHold,
    Resume,
    Override,
    BadOverride,
    Abort,
    EStop,
    Release,
    Reset
};
const char* name(Cmd c) {
    static const char* names[] = {"Load",  "Enable",   "Disable", "Home",       "Jog",
                                  "Start", "FeedHold", "Resume",  "Override80", "Override200",
                                  "Abort", "EStop",    "Release", "Reset"};
    return names[static_cast<int>(c)];
}

void send(SimCell& c, Cmd cmd) {
    MotionEngine& e = c.engine();
    switch (cmd) {
    case Cmd::Load:
        e.load(testProgram());
        break;
    case Cmd::Enable:
        e.enable();
        break;
    case Cmd::Disable:
        e.disable();
        break;
    case Cmd::Home:
        e.home();
        break;
    case Cmd::Jog:
        e.jog(2, deg2rad(5));
        break;
    case Cmd::Start:
        e.start();
        break;
    case Cmd::FeedHold:
        e.feedHold();
        break;
    case Cmd::Resume:
        e.resume();
        break;
    case Cmd::Override:
        e.setOverride(0.8);
        break;
    case Cmd::BadOverride:
        e.setOverride(2.0);
        break;
    case Cmd::Abort:
        e.abort();
        break;
    case Cmd::EStop:
        e.emergencyStop();
        break;
    case Cmd::Release:
        e.releaseEmergencyStop();
        break;
    case Cmd::Reset:
        e.reset();
        break;
    }
}

// Expected outcome: accepted with the state that follows, or refused with a reason fragment.
struct Outcome {
    bool accepted;
    EngineState state;
    const char* reason;
};
Outcome ok(EngineState s) {
    return {true, s, nullptr};
}
Outcome no(const char* why) {
    return {false, EngineState::Idle, why};
}

using S = EngineState;

struct Row {
    From from;
    std::vector<std::pair<Cmd, Outcome>> cases;
};

// The table follows the state machine (Idle -> Ready -> Running <-> Paused ->
// Completed; EmergencyStop latched until released and Reset; Fault until Reset).
const std::vector<Row>& table() {
    static const std::vector<Row> rows = {
        {From::Idle,
         {{Cmd::Load, ok(S::Idle)},
          {Cmd::Enable, ok(S::Idle)},
          {Cmd::Disable, no("not enabled")},
          {Cmd::Home, no("drives not enabled")},
          {Cmd::Jog, no("only while Ready")},
          {Cmd::Start, no("drives not enabled")},
          {Cmd::FeedHold, no("not running")},
          {Cmd::Resume, no("not paused")},
          {Cmd::Override, ok(S::Idle)},
          {Cmd::BadOverride, no("outside 10 .. 150 %")},
          {Cmd::Abort, no("nothing to abort")},
          {Cmd::EStop, ok(S::EmergencyStop)},
          {Cmd::Release, no("not pressed")},
          {Cmd::Reset, no("nothing to reset")}}},
        {From::ReadyUnhomed,
         {{Cmd::Load, ok(S::Ready)},
          {Cmd::Enable, no("already enabled")},
          {Cmd::Disable, ok(S::Idle)},
          {Cmd::Home, ok(S::Homing)},
          {Cmd::Jog, ok(S::Jogging)},
          {Cmd::Start, no("not homed")},
          {Cmd::FeedHold, no("not running")},
          {Cmd::Resume, no("not paused")},
          {Cmd::Override, ok(S::Ready)},
          {Cmd::BadOverride, no("outside")},
          {Cmd::Abort, no("nothing to abort")},
          {Cmd::EStop, ok(S::EmergencyStop)},
          {Cmd::Release, no("not pressed")},
          {Cmd::Reset, no("nothing to reset")}}},
        {From::ReadyHomed,
         {{Cmd::Load, ok(S::Ready)},
          {Cmd::Enable, no("already enabled")},
          {Cmd::Disable, ok(S::Idle)},
          {Cmd::Home, ok(S::Homing)},
          {Cmd::Jog, ok(S::Jogging)},
          {Cmd::Start, ok(S::Running)},
          {Cmd::FeedHold, no("not running")},
          {Cmd::Resume, no("not paused")},
          {Cmd::Override, ok(S::Ready)},
          {Cmd::BadOverride, no("outside")},
          {Cmd::Abort, no("nothing to abort")},
          {Cmd::EStop, ok(S::EmergencyStop)},
          {Cmd::Release, no("not pressed")},
          {Cmd::Reset, no("nothing to reset")}}},
        {From::Homing,
         {{Cmd::Load, no("motion is in progress")},
          {Cmd::Enable, no("already enabled")},
          {Cmd::Disable, no("motion in progress")},
          {Cmd::Home, no("already homing")},
          {Cmd::Jog, no("only while Ready")},
          {Cmd::Start, no("motion in progress")},
          {Cmd::FeedHold, no("not running")},
          {Cmd::Resume, no("not paused")},
          {Cmd::Override, ok(S::Homing)},
          {Cmd::BadOverride, no("outside")},
          {Cmd::Abort, ok(S::Homing)},
          {Cmd::EStop, ok(S::EmergencyStop)},
          {Cmd::Release, no("not pressed")},
          {Cmd::Reset, no("nothing to reset")}}},
        {From::Jogging,
         {{Cmd::Load, no("motion is in progress")},
          {Cmd::Enable, no("already enabled")},
          {Cmd::Disable, no("motion in progress")},
          {Cmd::Home, no("motion in progress")},
          {Cmd::Jog, no("only while Ready")},
          {Cmd::Start, no("motion in progress")},
          {Cmd::FeedHold, no("not running")},
          {Cmd::Resume, no("not paused")},
          {Cmd::Override, ok(S::Jogging)},
          {Cmd::BadOverride, no("outside")},
          {Cmd::Abort, ok(S::Jogging)},
          {Cmd::EStop, ok(S::EmergencyStop)},
          {Cmd::Release, no("not pressed")},
          {Cmd::Reset, no("nothing to reset")}}},
        {From::Running,
         {{Cmd::Load, no("motion is in progress")},
          {Cmd::Enable, no("already enabled")},
          {Cmd::Disable, no("motion in progress")},
          {Cmd::Home, no("motion in progress")},
          {Cmd::Jog, no("only while Ready")},
          {Cmd::Start, no("already running")},
          {Cmd::FeedHold, ok(S::Running)},
          {Cmd::Resume, no("not paused")},
          {Cmd::Override, ok(S::Running)},
          {Cmd::BadOverride, no("outside")},
          {Cmd::Abort, ok(S::Running)},
          {Cmd::EStop, ok(S::EmergencyStop)},
          {Cmd::Release, no("not pressed")},
          {Cmd::Reset, no("nothing to reset")}}},
        {From::Paused,
         {{Cmd::Load, no("motion is in progress")},
          {Cmd::Enable, no("already enabled")},
          {Cmd::Disable, no("motion in progress")},
          {Cmd::Home, no("motion in progress")},
          {Cmd::Jog, no("only while Ready")},
          {Cmd::Start, no("use Resume")},
          {Cmd::FeedHold, no("not running")},
          {Cmd::Resume, ok(S::Running)},
          {Cmd::Override, ok(S::Paused)},
          {Cmd::BadOverride, no("outside")},
          {Cmd::Abort, ok(S::Ready)},
          {Cmd::EStop, ok(S::EmergencyStop)},
          {Cmd::Release, no("not pressed")},
          {Cmd::Reset, no("nothing to reset")}}},
        {From::Completed,
         {{Cmd::Load, ok(S::Ready)},
          {Cmd::Enable, no("already enabled")},
          {Cmd::Disable, ok(S::Idle)},
          {Cmd::Home, ok(S::Homing)},
          {Cmd::Jog, no("only while Ready")},
          {Cmd::Start, no("cut is complete")},
          {Cmd::FeedHold, no("not running")},
          {Cmd::Resume, no("not paused")},
          {Cmd::Override, ok(S::Completed)},
          {Cmd::BadOverride, no("outside")},
          {Cmd::Abort, no("nothing to abort")},
          {Cmd::EStop, ok(S::EmergencyStop)},
          {Cmd::Release, no("not pressed")},
          {Cmd::Reset, no("nothing to reset")}}},
        {From::EStop,
         {{Cmd::Load, ok(S::EmergencyStop)},
          {Cmd::Enable, no("emergency stop latched")},
          {Cmd::Disable, no("already disabled")},
          {Cmd::Home, no("emergency stop latched")},
          {Cmd::Jog, no("only while Ready")},
          {Cmd::Start, no("emergency stop latched")},
          {Cmd::FeedHold, no("not running")},
          {Cmd::Resume, no("not paused")},
          {Cmd::Override, ok(S::EmergencyStop)},
          {Cmd::BadOverride, no("outside")},
          {Cmd::Abort, no("emergency stop latched")},
          {Cmd::EStop, ok(S::EmergencyStop)},
          {Cmd::Release, ok(S::EmergencyStop)},
          {Cmd::Reset, no("still pressed")}}},
        {From::Fault,
         {{Cmd::Load, ok(S::Fault)},
          {Cmd::Enable, no("fault latched")},
          {Cmd::Disable, no("already disabled")},
          {Cmd::Home, no("fault latched")},
          {Cmd::Jog, no("only while Ready")},
          {Cmd::Start, no("fault latched")},
          {Cmd::FeedHold, no("not running")},
          {Cmd::Resume, no("not paused")},
          {Cmd::Override, ok(S::Fault)},
          {Cmd::BadOverride, no("outside")},
          {Cmd::Abort, no("fault latched")},
          {Cmd::EStop, ok(S::EmergencyStop)},
          {Cmd::Release, no("not pressed")},
          {Cmd::Reset, ok(S::Idle)}}},
    };
    return rows;
}

class EveryCommandInEveryState : public ::testing::TestWithParam<From> {};

TEST_P(EveryCommandInEveryState, GivesANewStateOrARefusalWithItsReason) {
    const From from = GetParam();
    const Row* row = nullptr;
    for (const Row& r : table())
        if (r.from == from) row = &r;
    ASSERT_NE(row, nullptr);
    ASSERT_EQ(row->cases.size(), 14u) << "every command has a row";
    for (const auto& [cmd, expected] : row->cases) {
        SCOPED_TRACE(std::string(name(from)) + " + " + name(cmd));
        CellOptions quick;
        quick.quick = true;
        SimCell cell(quick);
        bringTo(cell, from);
        if (HasFatalFailure()) return;
        const EngineState before = cell.engine().state();
        const size_t mark = cell.events.size();
        send(cell, cmd);
        cell.cycleOnce();
        const EngineEvent* refusal = nullptr;
        const EngineEvent* transition = nullptr;
        for (size_t i = mark; i < cell.events.size(); ++i) {
            const EngineEvent& e = cell.events[i];
            if (e.kind == EventKind::Refusal && !refusal) refusal = &e;
            if ((e.kind == EventKind::Transition || e.kind == EventKind::Fault) && !transition)
                transition = &e;
        }
        const std::string text = cell.eventText(mark);
        if (expected.accepted) {
            EXPECT_EQ(refusal, nullptr) << text;
            const EngineState reached = transition ? transition->to : cell.engine().state();
            EXPECT_EQ(reached, expected.state) << text;
            EXPECT_GT(cell.events.size(), mark) << "an accepted command leaves an event";
        } else {
            ASSERT_NE(refusal, nullptr) << "expected a refusal, got:\n" << text;
            EXPECT_NE(std::string(refusal->text.data()).find(expected.reason), std::string::npos)
                << text;
            EXPECT_NE(std::string(refusal->text.data()).find("refused"), std::string::npos) << text;
            EXPECT_EQ(cell.engine().state(), before) << "a refusal leaves the state alone\n"
                                                     << text;
            EXPECT_GT(refusal->wall_ms, 0);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(AllStates, EveryCommandInEveryState,
                         ::testing::Values(From::Idle, From::ReadyUnhomed, From::ReadyHomed,
                                           From::Homing, From::Jogging, From::Running, From::Paused,
                                           From::Completed, From::EStop, From::Fault),
                         [](const ::testing::TestParamInfo<From>& i) {
                             return std::string(name(i.param));
                         });

TEST(EngineStateMachine, EnableReachesReadyAndHomingEndsAtTheReference) {
    SimCell cell;
    cell.engine().enable();
    cell.runUntil(EngineState::Ready);
    cell.engine().home();
    cell.cycleOnce();
    EXPECT_EQ(cell.engine().state(), EngineState::Homing);
    cell.keepTelemetry = true;
    cell.runUntil(EngineState::Ready);
    ASSERT_FALSE(cell.telemetry.empty());
    EXPECT_TRUE(cell.telemetry.back().homed);
    EXPECT_LT((cell.telemetry.back().setpoint - testProgram()->reference).norm(), 1e-12);
}

TEST(EngineStateMachine, JogOutsideTheAxisRangeIsRefusedWithTheLimit) {
    SimCell cell;
    cell.toReady(true);
    const size_t mark = cell.events.size();
    cell.engine().jog(2, deg2rad(60)); // theta2 range is -45 .. 45 deg
    cell.cycleOnce();
    const std::string text = cell.eventText(mark);
    EXPECT_NE(text.find("Jog refused: axis 2 (theta2) target 60.000 deg is outside its range "
                        "-45.000 .. 45.000 deg"),
              std::string::npos)
        << text;
    EXPECT_EQ(cell.engine().state(), EngineState::Ready);
}

} // namespace
} // namespace cutcell::test
