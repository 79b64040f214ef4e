#include "gui_run.h"

#include "ui/engine_bridge.h"
#include "ui/main_window.h"
#include "ui/panels/monitor_views.h"
#include "ui/panels/progress_panel.h"
#include "ui/run_controller.h"

#include <QAbstractButton>
#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QPixmap>
#include <QPointer>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

namespace cutcell::app {

using CutCell::ui::MainWindow;

namespace {
void saveAndExit(MainWindow& window, const QString& path);
} // namespace

void startUnattendedRun(MainWindow& window, const RunOptions& options) {
    auto* run = window.run();
    auto* watchdog = new QTimer(&window);
    watchdog->setSingleShot(true);
    QObject::connect(watchdog, &QTimer::timeout, &window, [&window] {
        std::fprintf(stderr,
                     "cutcell: the run did not complete within the timeout (state %s, %s)\n",
                     toString(window.run()->bridge()->state()),
                     window.progress()->percentText().toUtf8().constData());
        QApplication::exit(3);
    });
    watchdog->start(static_cast<int>(options.timeout_s * 1000));
    QObject::connect(
        run, &CutCell::ui::RunController::autoRunFinished, &window,
        [&window, options, watchdog](bool ok, const QString& reason) {
            watchdog->stop();
            if (!ok) {
                std::fprintf(stderr, "cutcell: run failed: %s\n", reason.toUtf8().constData());
                QApplication::exit(1);
                return;
            }
            std::printf("cutcell: run completed (%s, %llu plotted samples)\n",
                        window.progress()->percentText().toUtf8().constData(),
                        static_cast<unsigned long long>(window.plots()->samplesAppended()));
            if (options.screenshot.isEmpty()) {
                QApplication::exit(0);
                return;
            }
            // Let the last telemetry tick and the plots' 30 Hz replot land before grabbing.
            QTimer::singleShot(400, &window,
                               [&window, path = options.screenshot] { saveAndExit(window, path); });
        });
    run->startAutoRun();
}

namespace {

void saveAndExit(MainWindow& window, const QString& path) {
    window.run()->bridge()->poll();
    QImage shot = window.grab().toImage();
    if (!shot.isNull()) window.cellView()->paintFrameInto(shot, &window);
    if (shot.isNull() || !shot.save(path)) {
        std::fprintf(stderr, "cutcell: cannot write the screenshot %s\n",
                     path.toUtf8().constData());
        QApplication::exit(1);
        return;
    }
    std::printf("cutcell: screenshot %s (%dx%d)\n", path.toUtf8().constData(), shot.width(),
                shot.height());
    QApplication::exit(0);
}

} // namespace

bool startScreenshotOnly(MainWindow& window, const QString& path, const QString& press) {
    QPointer<QAbstractButton> button;
    if (!press.isEmpty()) {
        button = window.findChild<QAbstractButton*>(press);
        if (!button) {
            std::fprintf(stderr, "cutcell: --press: the window has no button %s\n",
                         press.toUtf8().constData());
            return false;
        }
        button->click();
    }
    auto* poll = new QTimer(&window);
    poll->setInterval(100);
    QObject::connect(poll, &QTimer::timeout, &window, [&window, poll, path, button] {
        if (window.run()->planning() || (button && !button->isEnabled())) return;
        poll->stop();
        QTimer::singleShot(400, &window, [&window, path] { saveAndExit(window, path); });
    });
    poll->start();
    return true;
}

namespace {

// Gaps between heartbeat ticks while the cut runs.
struct StallProbe {
    QElapsedTimer clock;
    qint64 lastNs = -1;
    bool measuring = false;
    std::vector<double> gapsMs;
};

} // namespace

void startStallBench(MainWindow& window, double seconds) {
    auto probe = std::make_shared<StallProbe>();
    probe->gapsMs.reserve(200000);
    auto* heartbeat = new QTimer(&window);
    heartbeat->setTimerType(Qt::PreciseTimer);
    heartbeat->setInterval(5);
    probe->clock.start();
    QObject::connect(heartbeat, &QTimer::timeout, &window, [probe] {
        const qint64 now = probe->clock.nsecsElapsed();
        if (probe->measuring && probe->lastNs >= 0)
            probe->gapsMs.push_back(static_cast<double>(now - probe->lastNs) / 1e6);
        probe->lastNs = now;
    });
    heartbeat->start();

    auto finish = [&window, probe, seconds](const char* end) {
        auto gaps = probe->gapsMs;
        std::sort(gaps.begin(), gaps.end());
        const auto pct = [&gaps](double p) {
            return gaps.empty() ? 0.0 : gaps[static_cast<size_t>(p * double(gaps.size() - 1))];
        };
        std::printf("{\"gui_max_stall_ms\": %.3f, \"gui_heartbeat_p50_ms\": %.3f, "
                    "\"gui_heartbeat_p99_ms\": %.3f, \"gui_tick_work_max_ms\": %.3f, "
                    "\"heartbeat_interval_ms\": 5, "
                    "\"heartbeats\": %zu, \"telemetry_samples\": %llu, \"plotted_samples\": %llu, "
                    "\"window_s\": %.1f, \"end\": \"%s\", \"state\": \"%s\"}\n",
                    gaps.empty() ? 0.0 : gaps.back(), pct(0.5), pct(0.99),
                    window.run()->bridge()->maxTickMs(), gaps.size(),
                    static_cast<unsigned long long>(window.run()->bridge()->samplesDrained()),
                    static_cast<unsigned long long>(window.plots()->samplesAppended()), seconds,
                    end, toString(window.run()->bridge()->state()));
        std::fflush(stdout);
        QApplication::exit(gaps.empty() ? 1 : 0);
    };
    auto* window_timer = new QTimer(&window);
    window_timer->setSingleShot(true);
    QObject::connect(window_timer, &QTimer::timeout, &window, [finish] { finish("window"); });
    QObject::connect(window.run()->bridge(), &CutCell::ui::EngineBridge::stateChanged, &window,
                     [probe, window_timer, seconds, &window](EngineState s) {
                         if (s == EngineState::Running && !probe->measuring) {
                             probe->measuring = true;
                             window.run()->bridge()->resetTickStats();
                             probe->lastNs = -1;
                             window_timer->start(static_cast<int>(seconds * 1000));
                         }
                     });
    QObject::connect(window.run(), &CutCell::ui::RunController::autoRunFinished, &window,
                     [finish](bool ok, const QString& reason) {
                         if (!ok)
                             std::fprintf(stderr, "cutcell: run failed: %s\n",
                                          reason.toUtf8().constData());
                         finish(ok ? "completed" : "failed");
                     });
    window.run()->startAutoRun();
}

} // namespace cutcell::app
