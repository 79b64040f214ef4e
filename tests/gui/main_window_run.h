#pragma once
// What the GUI run tests share: the engine's state as the window sees it, and an auto run
// (Enable, Home, Start through the RunController) waited for until the engine reports
// Completed.
#include "ui/engine_bridge.h"
#include "ui/main_window.h"
#include "ui/run_controller.h"

#include "ui/panels/control_panel.h"
#include "ui/panels/event_log_panel.h"

#include <QPushButton>
#include <QSignalSpy>
#include <QString>
#include <QStringList>
#include <QTest>

#include <algorithm>

// The event log's last lines, for a failure's message.
inline QString lastLog(const CutCell::ui::MainWindow& w, int lines = 8) {
    QStringList out;
    const int n = w.eventLog()->rowCount();
    for (int r = std::max(0, n - lines); r < n; ++r)
        out << w.eventLog()->message(r);
    return out.join(QStringLiteral("\n"));
}

inline cutcell::EngineState state(const CutCell::ui::MainWindow& w) {
    return w.run()->bridge()->state();
}

// True when the auto run finished without a failure within timeoutMs and the engine then
// reached Completed; otherwise false with *why saying what happened instead.
inline bool autoRunCompletes(CutCell::ui::MainWindow& w, int timeoutMs, QString* why) {
    QSignalSpy done(w.run(), &CutCell::ui::RunController::autoRunFinished);
    w.run()->startAutoRun();
    if (!done.wait(timeoutMs)) {
        *why = QStringLiteral("the auto run did not finish within %1 ms").arg(timeoutMs);
        return false;
    }
    if (!done.at(0).at(0).toBool()) {
        *why = done.at(0).at(1).toString();
        return false;
    }
    if (!QTest::qWaitFor([&] { return state(w) == cutcell::EngineState::Completed; }, 5000)) {
        *why = QStringLiteral("the auto run finished but the engine is not Completed");
        return false;
    }
    return true;
}

// Enable, Home and Start with the operator's buttons, each awaited (QTRY: a failure ends the
// calling test function).
inline void startManually(CutCell::ui::MainWindow& w) {
    using cutcell::EngineState;
    QTRY_VERIFY2_WITH_TIMEOUT(w.controls()->enableButton()->isEnabled() &&
                                  w.controls()->startBlockedReason().contains("Enable"),
                              qPrintable(w.controls()->startBlockedReason() + "\n" + lastLog(w)),
                              60000);
    QTest::mouseClick(w.controls()->enableButton(), Qt::LeftButton);
    QTRY_VERIFY2_WITH_TIMEOUT(state(w) == EngineState::Ready, cutcell::toString(state(w)), 5000);
    QTest::mouseClick(w.controls()->homeButton(), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(state(w) == EngineState::Ready && w.run()->bridge()->last().homed,
                             30000);
    QTRY_VERIFY2_WITH_TIMEOUT(w.controls()->startButton()->isEnabled(),
                              qPrintable(w.controls()->startBlockedReason()), 2000);
    QTest::mouseClick(w.controls()->startButton(), Qt::LeftButton);
    QTRY_VERIFY2_WITH_TIMEOUT(state(w) == EngineState::Running, cutcell::toString(state(w)), 10000);
}
