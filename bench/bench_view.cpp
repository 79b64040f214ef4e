// Frame time of the 3D view and replot time of the tracking plots, printed as JSON.
//
//   xvfb-run -a -s "-screen 0 1280x800x24" build/bench/bench_view        (3D view + plots)
//   QT_QPA_PLATFORM=offscreen build/bench/bench_view                      (plots only)
//   bench_view --screenshot cell.png   saves the default job's view instead of timing
//
// Options: --points N (path points, 30000), --frames N (100), --size WxH (800x600).
#include "core/geometry/cut_path.h"
#include "core/job/default_job.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "plots/tracking_plots_widget.h"
#include "ui/machines/pipe_robot/pipe_robot_scene.h"
#include "ui/view3d/cell_view.h"
#include "ui/view3d/scene_model.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <numeric>
#include <string>
#include <vector>

using namespace cutcell;

namespace {

struct Stats {
    double mean = 0, p95 = 0, min = 0, max = 0;
};

Stats stats(std::vector<double> v) {
    Stats s;
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    s.mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
    s.p95 = v[std::min(v.size() - 1,
                       static_cast<size_t>(std::ceil(0.95 * static_cast<double>(v.size()))) - 1)];
    s.min = v.front();
    s.max = v.back();
    return s;
}

void settle(int ms) {
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms) {
        QApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(5);
    }
}

CutPlan planWithPoints(Job& job, int points) {
    const CutGeometry geo(job);
    job.cut.knot_spacing_mm = geo.length() / points;
    return planCut(job);
}

} // namespace

int main(int argc, char** argv) {
    int points = 30000, frames = 100, width = 800, height = 600;
    std::string screenshot;
    bool follow = false;
    double joint3MaxDeg = 1e9; // --joint3-max: shrink joint 3's range to show unreachable points
    for (int i = 1; i < argc; ++i) {
        const auto next = [&] { return i + 1 < argc ? argv[++i] : ""; };
        if (!std::strcmp(argv[i], "--points"))
            points = std::max(16, std::atoi(next()));
        else if (!std::strcmp(argv[i], "--frames"))
            frames = std::max(1, std::atoi(next()));
        else if (!std::strcmp(argv[i], "--size"))
            std::sscanf(next(), "%dx%d", &width, &height);
        else if (!std::strcmp(argv[i], "--screenshot"))
            screenshot = next();
        else if (!std::strcmp(argv[i], "--follow"))
            follow = true;
        else if (!std::strcmp(argv[i], "--joint3-max"))
            joint3MaxDeg = std::atof(next());
        else {
            std::fprintf(stderr, "usage: bench_view [--points N] [--frames N] [--size WxH] "
                                 "[--screenshot file.png [--follow] [--joint3-max deg]]\n");
            return 2;
        }
    }
    view3d::CellView::setDefaultSurfaceFormat();
    QApplication app(argc, argv);

    if (!screenshot.empty()) {
        Job job = defaultJob();
        cutcell::pipeRobotSpec(job).dh[3].max_deg =
            std::min(cutcell::pipeRobotSpec(job).dh[3].max_deg, joint3MaxDeg);
        const CutPlan plan = planCut(job);
        view3d::CellView view;
        view.resize(width, height);
        view.show();
        view.setScene(view3d::buildRobotScene(job, plan));
        if (follow) view.setPreset(view3d::ViewPreset::FollowTorch);
        const double f = 0.4;
        view.setMachineState(plan.spline.evaluate(f * plan.spline.duration()).q, f, true);
        settle(300);
        const QImage img = view.grabFrame();
        if (img.isNull() || !img.save(QString::fromStdString(screenshot))) {
            std::fprintf(stderr, "no frame: OpenGL unavailable on platform '%s'\n",
                         qPrintable(QGuiApplication::platformName()));
            return 1;
        }
        std::printf("saved %s (%dx%d)\n", screenshot.c_str(), img.width(), img.height());
        return 0;
    }

    std::printf("{\n  \"platform\": \"%s\",\n", qPrintable(QGuiApplication::platformName()));

    // 3D view: one render per frame while the machine moves along a 30 000-point path.
    if (view3d::CellView::openGlAvailable()) {
        Job job = defaultJob();
        QElapsedTimer t;
        t.start();
        const CutPlan plan = planWithPoints(job, points);
        const double planMs = static_cast<double>(t.nsecsElapsed()) / 1e6;
        view3d::CellView view;
        view.show();
        settle(100);
        // Size the GL area itself to width x height (the toolbar sits above it).
        view.resize(width, height + (view.height() - view.findChild<QOpenGLWidget*>()->height()));
        t.restart();
        view.setScene(view3d::buildRobotScene(job, plan));
        const double sceneMs = static_cast<double>(t.nsecsElapsed()) / 1e6;
        settle(300);
        std::vector<double> frameMs, stateMs, cpuMs;
        const int warmup = 5;
        for (int i = 0; i < frames + warmup; ++i) {
            const double f = static_cast<double>(i) / (frames + warmup - 1);
            t.restart();
            view.setMachineState(plan.spline.evaluate(f * plan.spline.duration()).q, f, true);
            const double s = static_cast<double>(t.nsecsElapsed()) / 1e6;
            timespec c0{}, c1{};
            clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
            const double ms = view.renderFrameMs();
            clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
            if (i >= warmup)
                cpuMs.push_back(static_cast<double>(c1.tv_sec - c0.tv_sec) * 1e3 +
                                static_cast<double>(c1.tv_nsec - c0.tv_nsec) / 1e6);
            if (i >= warmup) {
                frameMs.push_back(ms);
                stateMs.push_back(s);
            }
        }
        const Stats fs = stats(frameMs), ss = stats(stateMs);
        const QOpenGLWidget* gl = view.findChild<QOpenGLWidget*>();
        std::printf(
            "  \"view_path_points\": %zu,\n  \"view_size\": \"%dx%d\",\n  \"view_frames\": %d,\n",
            plan.knots.size(), gl->width(), gl->height(), frames);
        std::printf(
            "  \"view_frame_ms\": {\"mean\": %.3f, \"p95\": %.3f, \"min\": %.3f, \"max\": %.3f},\n",
            fs.mean, fs.p95, fs.min, fs.max);
        const Stats cs = stats(cpuMs);
        std::printf(
            "  \"view_frame_cpu_ms\": {\"mean\": %.3f, \"p95\": %.3f, \"note\": \"CPU time of the "
            "process "
            "per frame (llvmpipe renders on the CPU), less sensitive to a loaded machine\"},\n",
            cs.mean, cs.p95);
        std::printf("  \"view_set_state_ms\": {\"mean\": %.3f, \"p95\": %.3f},\n", ss.mean, ss.p95);
        std::printf("  \"view_set_scene_ms\": %.3f,\n  \"plan_ms\": %.3f,\n", sceneMs, planMs);
    } else {
        std::printf(
            "  \"view_frame_ms\": null,\n  \"view_note\": \"no OpenGL on this platform; run under "
            "xvfb-run\",\n");
    }

    // Plots: 6 joint traces (+3 Cartesian) x 30 000 samples, 1200x700.
    plots::TrackingPlotsWidget plot;
    plot.resize(1200, 700);
    plot.show();
    settle(100);
    const int samples = 30000;
    plot.setCapacity(samples);
    QElapsedTimer t;
    t.start();
    for (int i = 0; i < samples; ++i) {
        const double ts = i * 0.001;
        double e[6], c[3];
        for (int k = 0; k < 6; ++k)
            e[k] = 0.01 * (k + 1) * std::sin(2 * kPi * (0.3 + 0.1 * k) * ts);
        for (int k = 0; k < 3; ++k)
            c[k] = 0.05 * std::cos(2 * kPi * (0.5 + 0.2 * k) * ts);
        plot.append(ts, e, 6, c);
    }
    const double appendNs = static_cast<double>(t.nsecsElapsed()) / samples;
    std::vector<double> replot;
    for (int i = 0; i < 20; ++i)
        replot.push_back(plot.replotNow());
    const Stats rs = stats(replot);
    std::printf("  \"plot_points_per_trace\": %d,\n  \"append_ns_per_sample\": %.1f,\n",
                plot.plottedPointCount(), appendNs);
    std::printf(
        "  \"replot_ms_6x30000\": {\"mean\": %.3f, \"p95\": %.3f, \"min\": %.3f, \"max\": %.3f, "
        "\"note\": \"both plots: 6 joint + 3 Cartesian traces\"}\n}\n",
        rs.mean, rs.p95, rs.min, rs.max);
    return 0;
}
