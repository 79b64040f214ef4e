// cutcell: the operator station of the cutting cell (Qt Widgets).
#include "gui_run.h"
#include "production_record.h"
#include "shopfloor_station.h"

#include "core/process/cut_chart_library.h"
#include "sim_rig.h"
#include "station_access.h"
#include "ui/access_control.h"
#include "ui/panels/cut_charts_dialog.h"

#include "devices/process/safe_shutdown.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/main_window.h"
#include "ui/panels/monitor_views.h"
#include "ui/run_controller.h"
#include "ui/theme.h"
#ifdef CUTCELL_HAVE_VIEW3D
#include "ui/view3d/cell_view.h"
#endif

#include "ui/language.h"
#include "ui/window_host.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QMessageBox>
#include <QTabWidget>
#include <QTimer>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

namespace {

// Qt aborts with a cryptic message when no platform can be opened: say what to do instead.
bool displayAvailable(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "-platform") || !std::strcmp(argv[i], "--platform") ||
            !std::strncmp(argv[i], "-platform=", 10) || !std::strncmp(argv[i], "--platform=", 11))
            return true;
    for (const char* var : {"QT_QPA_PLATFORM", "DISPLAY", "WAYLAND_DISPLAY"}) {
        const char* v = std::getenv(var);
        if (v && *v) return true;
    }
    return false;
}

bool wantsHelp(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) return true;
    return false;
}

} // namespace

int main(int argc, char** argv) {
    if (!wantsHelp(argc, argv) && !displayAvailable(argc, argv)) {
        std::fputs("cutcell: no display: run with --platform offscreen (or under xvfb-run), "
                   "or use cutcell-cli for headless work\n",
                   stderr);
        return 2;
    }
#ifdef CUTCELL_HAVE_VIEW3D
    cutcell::view3d::CellView::setDefaultSurfaceFormat(); // before QApplication
#endif
    QApplication app(argc, argv);
    // Any ending (signal, std::terminate) first brings the cell to a safe state (the rigs
    // register how), then quits the event loop: the window closes in order.
    cutcell::SafeShutdown::install();
    cutcell::SafeShutdown::setOnRequest([](int) {
        QMetaObject::invokeMethod(qApp, &QCoreApplication::quit, Qt::QueuedConnection);
    });
    QApplication::setOrganizationName(QStringLiteral("CutCell"));
    QApplication::setApplicationName(QStringLiteral("cutcell"));
    QApplication::setApplicationVersion(QStringLiteral("0.1.0"));
    // The user's cut-chart table before any job is read (a job's cut speed comes from it).
    if (const QString why = CutCell::ui::installCutChartsInUse(cutcell::defaultDataHome());
        !why.isEmpty())
        std::fprintf(stderr, "cutcell: the user's cut charts are not used: %s\n", qPrintable(why));

    QCommandLineParser cli;
    cli.setApplicationDescription(
        QStringLiteral("CutCell operator station. Qt options such as --platform offscreen "
                       "are accepted."));
    cli.addHelpOption();
    cli.addVersionOption();
    const QCommandLineOption jobOpt("job", "Open the job FILE (default: the built-in job).",
                                    "FILE");
    const QCommandLineOption runOpt(
        "run", "Run the job on the simulated cell (as fast as possible) and quit when it ends.");
    const QCommandLineOption realTimeOpt("realtime", "With --run: pace the run to the wall clock.");
    const QCommandLineOption shotOpt(
        "screenshot", "Save the main window to PNG and quit (with --run: when the run completed).",
        "PNG");
    const QCommandLineOption sizeOpt(
        "size",
        "Window size WIDTHxHEIGHT (default: 1600x1000, within the screen's available area).",
        "WxH");
    const QCommandLineOption timeoutOpt("timeout", "With --run: give up after S seconds.", "S",
                                        "300");
    const QCommandLineOption benchOpt(
        "bench-stall",
        "Measure the longest GUI-thread stall during a real-time run of S "
        "seconds; prints JSON.",
        "S");
    const QCommandLineOption tabOpt("tab",
                                    "Show the N-th parameter tab the job's machine has (0 = Job, 1 "
                                    "= Pipes or the machine's first page, ...).",
                                    "N", "0");
    const QCommandLineOption languageOpt(
        "language",
        "The GUI's language: system (the desktop's), en or de (default: the one chosen last in "
        "the Language menu, else system). Not remembered.",
        "CODE");
    const QCommandLineOption viewOpt(
        "view", "The 3D view's preset at the start: iso, front, top or follow (the tool).",
        "PRESET", "iso");
    const QCommandLineOption recordOpt(
        "record",
        "The production record the runs, users and audit trail go to: a SQLite FILE, a "
        "PostgreSQL server shared by the shop's cells (postgresql://user@host:port/db), or off "
        "(default: $XDG_DATA_HOME/cutcell/production.db; `cutcell-cli history` lists it).",
        "FILE|URL");
    const QCommandLineOption pressOpt(
        "press",
        "With --screenshot: click the push button of this object name first (e.g. "
        "compareMethods on the robot's Method page) and take the shot once it is enabled "
        "again.",
        "NAME");
    const QCommandLineOption shopfloorOpt(
        "shopfloor",
        "The shop-floor link's configuration (Sparkplug B over MQTT; devices/shopfloor/README.md), "
        "or off (default: $XDG_CONFIG_HOME/cutcell/shopfloor.json when it exists).",
        "FILE");
    cli.addOptions({jobOpt, runOpt, realTimeOpt, shotOpt, sizeOpt, timeoutOpt, benchOpt, tabOpt,
                    languageOpt, viewOpt, recordOpt, pressOpt, shopfloorOpt});
    cli.addPositionalArgument("FILE", "The job to open, as with --job (one at most).", "[FILE]");
    cli.process(app);

    // `cutcell job.json` opens the job as `--job job.json` does (a file manager passes it so);
    // before, the file was ignored without a word and the built-in job came up instead.
    const QStringList files = cli.positionalArguments();
    if (files.size() > 1 || (files.size() == 1 && cli.isSet(jobOpt))) {
        std::fprintf(stderr, "cutcell: one job at a time: got %s%s (see cutcell --help)\n",
                     cli.isSet(jobOpt) ? "--job and " : "",
                     qPrintable(files.join(QStringLiteral(", "))));
        return 64;
    }
    const QString jobFile = files.isEmpty() ? cli.value(jobOpt) : files.front();

    const QStringList size = cli.value(sizeOpt).split('x');
    if (cli.isSet(sizeOpt) &&
        (size.size() != 2 || size[0].toInt() < 320 || size[1].toInt() < 240)) {
        std::fprintf(stderr, "cutcell: --size must be WIDTHxHEIGHT, e.g. 1440x900\n");
        return 64;
    }
    using cutcell::view3d::ViewPreset;
    const std::map<QString, ViewPreset> presets = {{"iso", ViewPreset::Iso},
                                                   {"front", ViewPreset::Front},
                                                   {"top", ViewPreset::Top},
                                                   {"follow", ViewPreset::FollowTorch}};
    const auto preset = presets.find(cli.value(viewOpt));
    if (preset == presets.end()) {
        std::fprintf(stderr, "cutcell: --view must be iso, front, top or follow, not '%s'\n",
                     qPrintable(cli.value(viewOpt)));
        return 64;
    }
    CutCell::ui::applyDarkIndustrialTheme(app);
    const QString language =
        cli.isSet(languageOpt) ? cli.value(languageOpt) : CutCell::ui::rememberedLanguage();
    QString languageWhy;
    if (!CutCell::ui::applyGuiLanguage(language, &languageWhy)) {
        std::fprintf(stderr, "cutcell: --language: %s\n", qPrintable(languageWhy));
        if (cli.isSet(languageOpt)) return 64;
    }
    // The host rebuilds the window for a change of language (Language menu); unattended runs
    // below hold the first window, which no menu replaces while they run.
    // Before any rig: each engine is told of the record as it is made.
    std::fprintf(stderr, "cutcell: %s\n",
                 cutcell::app::openProductionRecord(cli.value(recordOpt).toStdString()).c_str());
    std::fprintf(stderr, "cutcell: %s\n",
                 cutcell::app::openStationAccess(cli.value(recordOpt).toStdString()).c_str());
    QObject::connect(&app, &QCoreApplication::aboutToQuit, [] {
        if (auto* access = cutcell::app::stationAccess()) access->logOut("the station closed");
    });
    std::fprintf(stderr, "cutcell: %s\n",
                 cutcell::app::openShopfloor(cli.value(shopfloorOpt).toStdString()).c_str());
    QObject::connect(&app, &QCoreApplication::aboutToQuit, [] { cutcell::app::closeShopfloor(); });
    CutCell::ui::WindowHost host(&cutcell::app::makeRig);
    cutcell::app::attachStationAccess(*host.window());
    cutcell::app::attachShopfloor(*host.window());
    QObject::connect(&host, &CutCell::ui::WindowHost::windowRebuilt,
                     [](CutCell::ui::MainWindow* rebuilt) {
                         cutcell::app::attachStationAccess(*rebuilt);
                         cutcell::app::attachShopfloor(*rebuilt);
                     });
    CutCell::ui::MainWindow& window = *host.window();
    // Without --size the window fits the screen it opens on (MainWindow::fitToScreen): a fixed
    // 1440x900 put the E-STOP column off a 1280x720 panel.
    if (cli.isSet(sizeOpt)) window.resize(size[0].toInt(), size[1].toInt());
    const bool bench = cli.isSet(benchOpt);
    const bool unattended = bench || cli.isSet(runOpt) || cli.isSet(shotOpt);
    // Unattended runs report on stderr and exit codes; never wait on a dialog.
    if (unattended) window.setErrorPrompt([](const QString&, const QString&) {});
    QString openError;
    if (cli.isSet(runOpt) && !cli.isSet(realTimeOpt) && !bench)
        window.run()->setClockMode(cutcell::ClockMode::AsFastAsPossible);
    if (!jobFile.isEmpty()) {
        if (!window.openJob(jobFile, &openError)) {
            std::fprintf(stderr, "cutcell: %s\n", openError.toUtf8().constData());
            if (cli.isSet(runOpt) || bench) return 1;
        }
    }
    window.parameters()->showVisibleTab(cli.value(tabOpt).toInt());
    window.cellView()->view()->setPreset(preset->second);
    window.show();
    if (!openError.isEmpty() && !unattended) // the window was not on screen when it failed
        QTimer::singleShot(0, &window, [&window, openError] {
            QMessageBox::critical(&window, QObject::tr("Cannot open the job"), openError);
        });
    if (bench) {
        bool ok = false;
        const double seconds = cli.value(benchOpt).toDouble(&ok);
        if (!ok || seconds <= 0) {
            std::fprintf(stderr, "cutcell: --bench-stall needs a number of seconds > 0\n");
            return 64;
        }
        cutcell::app::startStallBench(window, seconds);
    } else if (cli.isSet(runOpt)) {
        cutcell::app::RunOptions opt;
        opt.screenshot = cli.value(shotOpt);
        opt.timeout_s = cli.value(timeoutOpt).toDouble();
        if (opt.timeout_s <= 0) opt.timeout_s = 300;
        cutcell::app::startUnattendedRun(window, opt);
    } else if (cli.isSet(shotOpt)) {
        if (!cutcell::app::startScreenshotOnly(window, cli.value(shotOpt), cli.value(pressOpt)))
            return 64;
    }
    return app.exec();
}
