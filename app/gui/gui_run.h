#pragma once
// Unattended modes of the GUI: `--run --screenshot PNG` (run the job on the simulated cell,
// grab the main window when it completes) and `--bench-stall SECONDS` (longest GUI-thread
// stall during a real-time run, measured with a 5 ms heartbeat timer).
#include <QObject>
#include <QString>

namespace CutCell::ui {
class MainWindow;
}

namespace cutcell::app {

struct RunOptions {
    QString screenshot;     // empty: no screenshot
    double timeout_s = 300; // the whole run, planning included
};

// Starts the run; the application exits with 0 when it completed (and the screenshot was
// written), 1 on a fault, an emergency stop or an unreachable path, 3 on timeout.
void startUnattendedRun(CutCell::ui::MainWindow& window, const RunOptions& options);

// Saves the main window to `path` once planning has settled (no run), then exits 0. With
// `press` (a push button's object name, e.g. the robot's "compareMethods"), first clicks that
// button and waits until it is enabled again (the page's own work done). False, with the
// reason on stderr, when the window has no such button.
bool startScreenshotOnly(CutCell::ui::MainWindow& window, const QString& path,
                         const QString& press = {});

// Runs the current job in real time for `seconds` (or to completion) and prints
// {"gui_max_stall_ms": ...} on stdout, then exits.
void startStallBench(CutCell::ui::MainWindow& window, double seconds);

} // namespace cutcell::app
