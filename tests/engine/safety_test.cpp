// Emergency stop and faults: the devices are stopped, the state latches, and the event names
// the axis, the fault and the values.
#include "engine_fixture.h"

#include <cmath>
#include <functional>

namespace cutcell::test {
namespace {

struct StateSetup {
    const char* name;
    std::function<void(SimCell&)> go;
};

// Engine time of the first event since `from` whose text contains `fragment` (NaN if none).
double eventTime(const SimCell& cell, const char* fragment, size_t from = 0) {
    for (size_t i = from; i < cell.events.size(); ++i)
        if (std::string(cell.events[i].text.data()).find(fragment) != std::string::npos)
            return cell.events[i].time_s;
    return std::nan("");
}

std::vector<StateSetup> everyState() {
    return {
        {"Idle", [](SimCell&) {}},
        {"Ready", [](SimCell& c) { c.toReady(true); }},
        {"Homing", [](SimCell& c) { c.toHoming(); }},
        {"Jogging", [](SimCell& c) { c.toJogging(); }},
        {"Running", [](SimCell& c) { c.toCutting(1.0); }},
        {"Paused", [](SimCell& c) { c.toPaused(); }},
        {"Completed", [](SimCell& c) { c.toCompleted(); }},
        {"Fault", [](SimCell& c) { c.toFault(); }},
    };
}

TEST(EmergencyStop, FromEveryStateStopsTheDevicesAndLatchesUntilReleasedAndReset) {
    for (const auto& s : everyState()) {
        SCOPED_TRACE(s.name);
        CellOptions quick;
        quick.quick = true;
        SimCell cell(quick);
        s.go(cell);
        if (HasFatalFailure()) return;
        const std::uint64_t measured = cell.engine().cycleStats().estops_measured;
        const size_t before = cell.events.size();
        cell.engine().emergencyStop();
        cell.cycleOnce();
        EXPECT_EQ(cell.engine().state(), EngineState::EmergencyStop);
        EXPECT_FALSE(cell.torch().isOn());
        EXPECT_TRUE(cell.drivesAllDisabled());
        // Category 0: commanded off and seen off within the cycle that took the request.
        EXPECT_EQ(cell.engine().cycleStats().estops_measured, measured + 1);
        const double requested = eventTime(cell, "Emergency stop (", before);
        EXPECT_EQ(eventTime(cell, "Emergency stop complete", before), requested)
            << cell.eventText(before);
        // Latched: nothing moves it but release + reset.
        cell.engine().enable();
        cell.engine().start();
        cell.engine().reset();
        cell.run(50, EngineState::Idle);
        EXPECT_EQ(cell.engine().state(), EngineState::EmergencyStop);
        EXPECT_NE(cell.eventText().find("Reset refused: the emergency stop is still pressed"),
                  std::string::npos);
        cell.engine().releaseEmergencyStop();
        cell.run(5, EngineState::Idle);
        EXPECT_EQ(cell.engine().state(), EngineState::EmergencyStop)
            << "release alone does not clear";
        cell.engine().reset();
        cell.cycleOnce();
        EXPECT_EQ(cell.engine().state(), EngineState::Idle);
        // And the cell works again: enable, home.
        cell.engine().enable();
        cell.runUntil(EngineState::Ready);
    }
}

TEST(EmergencyStop, CategoryOneStopsAlongThePathThenDisables) {
    CellOptions o;
    o.category = StopCategory::Cat1;
    SimCell cell(o);
    cell.toCutting(3.0);
    cell.keepTelemetry = true;
    const std::uint64_t measured = cell.engine().cycleStats().estops_measured;
    const size_t before = cell.events.size();
    cell.engine().emergencyStop();
    cell.cycleOnce();
    EXPECT_EQ(cell.engine().state(), EngineState::EmergencyStop);
    EXPECT_FALSE(cell.torch().isOn()) << "the torch goes out at once in both categories";
    EXPECT_EQ(cell.telemetry.back().drive_states[1], DriveState::Enabled)
        << "category 1 decelerates first";
    cell.run(2000, EngineState::Idle);
    EXPECT_TRUE(cell.drivesAllDisabled());
    EXPECT_EQ(cell.engine().cycleStats().estops_measured, measured + 1);
    // The path rate ramps from 1 to 0 in feed_hold_decel_s, then the drives are disabled and
    // seen off: the stop completes that long after the request, plus at most a few cycles.
    const double T = testJob().sim.period_s, decel = testJob().engine.feed_hold_decel_s;
    const double took = eventTime(cell, "Emergency stop complete", before) -
                        eventTime(cell, "Emergency stop (", before);
    EXPECT_GE(took, decel - 1e-9) << cell.eventText(before);
    EXPECT_LE(took, decel + 3 * T) << cell.eventText(before);
    EXPECT_NE(cell.eventText().find("Controlled stop complete"), std::string::npos);
}

struct FaultCase {
    const char* name;
    std::function<void(SimCell&)> inject;
    std::vector<std::string> fragments;
};

TEST(Faults, EachInjectedFaultEndsInFaultWithTheRightMessage) {
    const std::vector<FaultCase> cases = {
        {"drive fault code",
         [](SimCell& c) { c.drive(2).injectFault(0x7500); },
         {"Fault: axis 2 (theta2): drive fault 0x7500 at", "deg (set-point"}},
        {"following error (collision load)",
         [](SimCell& c) { c.drive(0).injectLoadTorque(-40); },
         {"Fault: axis 0 (chuck (theta0)): following error", "exceeds 2.000 deg", "set-point",
          "actual"}},
        {"frozen feedback",
         [](SimCell& c) { c.drive(0).injectFrozenFeedback(true); },
         {"Fault: axis 0 (chuck (theta0)): feedback frozen at", "while the set-point moved"}},
        {"stale feedback",
         [](SimCell& c) { c.drive(4).injectStaleFeedback(true); },
         {"Fault: axis 4 (theta4): feedback not valid"}},
        {"arc lost",
         [](SimCell& c) { c.torch().injectArcLoss(true); },
         {"Fault: torch: arc lost at point", "of 131 (path time"}},
    };
    for (const auto& fc : cases) {
        SCOPED_TRACE(fc.name);
        CellOptions quick;
        quick.quick = true;
        SimCell cell(quick);
        cell.toCutting(2.0);
        if (HasFatalFailure()) return;
        const size_t mark = cell.events.size();
        fc.inject(cell);
        cell.runUntil(EngineState::Fault, 20000);
        const std::string text = cell.eventText(mark);
        for (const auto& f : fc.fragments)
            EXPECT_NE(text.find(f), std::string::npos) << f << "\n" << text;
        EXPECT_FALSE(cell.torch().isOn());
        EXPECT_TRUE(cell.drivesAllDisabled()) << "category 0 stop";
        TrackingReport r;
        std::string outcome;
        ASSERT_TRUE(cell.engine().lastRunReport(r, &outcome));
        EXPECT_EQ(outcome.rfind("fault: ", 0), 0u) << outcome;
        // Reset clears it; the fault does not come back by itself once the cause is gone.
        cell.drive(0).clearInjections();
        cell.drive(4).clearInjections();
        cell.torch().clearInjections();
        cell.engine().reset();
        cell.cycleOnce();
        EXPECT_EQ(cell.engine().state(), EngineState::Idle);
    }
}

TEST(Faults, CategoryOneFaultReactionStopsTheHealthyAxesAlongThePath) {
    CellOptions o;
    o.category = StopCategory::Cat1;
    SimCell cell(o);
    cell.toCutting(3.0);
    cell.keepTelemetry = true;
    cell.drive(5).injectFault(0x3210);
    cell.cycleOnce();
    EXPECT_EQ(cell.engine().state(), EngineState::Fault);
    EXPECT_FALSE(cell.torch().isOn());
    EXPECT_EQ(cell.telemetry.back().drive_states[1], DriveState::Enabled)
        << "healthy axes decelerate first";
    cell.run(2000, EngineState::Idle);
    EXPECT_TRUE(cell.drivesAllDisabled());
    const std::string text = cell.eventText();
    EXPECT_NE(text.find("Fault: axis 5 (theta5): drive fault 0x3210"), std::string::npos) << text;
    EXPECT_NE(text.find("cat1 stop"), std::string::npos) << text;
    EXPECT_NE(text.find("Controlled stop complete: drives disabled"), std::string::npos) << text;
    cell.drive(5).clearInjections();
    cell.engine().reset();
    cell.cycleOnce();
    EXPECT_EQ(cell.engine().state(), EngineState::Idle);
}

TEST(Faults, StartBeforeHomingIsRefusedWithTheReason) {
    SimCell cell;
    cell.toReady(false);
    const size_t mark = cell.events.size();
    cell.engine().start();
    cell.cycleOnce();
    EXPECT_NE(cell.eventText(mark).find("Start refused: not homed (Home first)"),
              std::string::npos);
}

} // namespace
} // namespace cutcell::test
