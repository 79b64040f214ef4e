#include "ui/main_window.h"
#include "ui/shown_number.h"

#include "core/job/default_job.h"
#include "core/machine/machine_registry.h"
#include "ui/device_panel.h"
#include "ui/file_places.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/help_menu.h"
#include "ui/job_document.h"
#include "ui/job_import.h"
#include "ui/language.h"
#include "ui/machine/machine_choice.h"
#include "ui/machine/machine_ui_registry.h"
#include "ui/machine_exports.h"
#include "ui/machine_views.h"
#include "ui/panels/alarm_panel.h"
#include "ui/panels/bus_panel.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/dro_panel.h"
#include "ui/panels/elided_label.h"
#include "ui/panels/engine_text.h"
#include "ui/panels/event_log_panel.h"
#include "ui/panels/monitor_views.h"
#include "ui/panels/progress_panel.h"
#include "ui/panels/recovery_panel.h"
#include "ui/panels/run_words.h"
#include "ui/panels/state_lamps.h"
#include "ui/plan_worker.h"
#include "ui/run_controller.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFrame>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QShowEvent>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::EngineState;
using cutcell::Severity;

MainWindow::MainWindow(EngineRigFactory factory, QWidget* parent)
    : QMainWindow(parent), editor_(new JobEditor(this)), document_(new JobDocument(editor_, this)),
      run_(new RunController(editor_, std::move(factory), this)) {
    setObjectName("mainWindow");
    buildLayout();
    buildMenus();
    connectRun();
    connect(document_, &JobDocument::changed, this, &MainWindow::refreshTitle);
    connect(editor_, &JobEditor::edited, this, &MainWindow::refreshTitle);
    connect(document_, &JobDocument::recentFilesChanged, this, &MainWindow::refreshRecentMenu);
    document_->newJob(cutcell::defaultJob());
    refreshRecentMenu();
    fitToScreen();
}

MainWindow::~MainWindow() = default;

void MainWindow::showMachineTerms() {
    const cutcell::MachineModule* machine = cutcell::findMachine(editor_->job().machine);
    const cutcell::RunTerms terms = machine ? machine->runTerms() : cutcell::RunTerms{};
    alarms_->setTerms(terms);
    lamps_->setToolName(toolWord(terms));
    cell_->setToolName(toolWord(terms));
    // The plots name the job's axes before any plan (an invalid job showed the robot's).
    if (const MachineUi* ui = machineUiFor(editor_->job())) plots_->setMachine(*ui);
}

void MainWindow::buildLayout() {
    params_ = new ParameterTabs(editor_, this);
    params_->setMinimumWidth(420);
    run_->setIssueDescriber(
        [this](const cutcell::JobIssue& i) { return params_->issueMessage(i); });
    run_->setKeyLabeller([this](const QString& text) { return params_->withFieldLabels(text); });
    cell_ = new CellViewPanel(this);
    plots_ = new PlotsPanel(this);
    controls_ = new ControlPanel(this);
    lamps_ = new StateLamps(this);
    progress_ = new ProgressPanel(this);
    log_ = new EventLogPanel(this);
    devices_ = new cutcell::ui::DevicePanel(this);
    devices_->setObjectName("devicePanel");
    devices_->setChoiceVisible(false); // chosen in the "Cycle & devices" parameter tab
    devices_->setTextTranslator(&engineText);
    dro_ = new DroPanel(this);
    alarms_ = new AlarmPanel(this);
    recovery_ = new RecoveryPanel(this);
    bus_ = new BusPanel(this); // shown for a rig with a bus

    auto* centre = new QSplitter(Qt::Vertical, this);
    centre->setObjectName("centreSplitter");
    centre->addWidget(cell_);
    centre->addWidget(plots_);
    centre->setStretchFactor(0, 3);
    centre->setStretchFactor(1, 2);
    centre->setSizes({600, 360});
    centre->setChildrenCollapsible(false);

    // The operator column: E-STOP and the buttons first, always on screen; lamps, progress and
    // the position readout below them scroll when the window is short (1280x720), so nothing
    // is ever cut.
    auto* column = new QFrame(this);
    column_ = column;
    column->setObjectName("operatorColumn");
    column->setFixedWidth(320);
    auto* cv = new QVBoxLayout(column);
    cv->setContentsMargins(0, 0, 0, 0);
    cv->setSpacing(0);
    cv->addWidget(controls_);
    auto* status = new QWidget;
    status->setObjectName("operatorStatus");
    auto* sv = new QVBoxLayout(status);
    statusLayout_ = sv;
    sv->setContentsMargins(0, 0, 0, 0);
    sv->addWidget(lamps_);
    sv->addWidget(bus_);
    sv->addWidget(progress_);
    sv->addWidget(recovery_);
    sv->addWidget(dro_);
    sv->addStretch(1);
    auto* statusScroll = new QScrollArea(column);
    statusScroll->setObjectName("operatorStatusScroll");
    statusScroll->setWidget(status);
    statusScroll->setWidgetResizable(true);
    statusScroll->setFrameShape(QFrame::NoFrame);
    statusScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    cv->addWidget(statusScroll, 1);

    auto* top = new QSplitter(Qt::Horizontal, this);
    top->addWidget(params_);
    top->addWidget(centre);
    top->setStretchFactor(0, 0);
    top->setStretchFactor(1, 1);
    top->setSizes({440, 900});

    auto* main = new QSplitter(Qt::Vertical, this);
    main->setObjectName("mainSplitter");
    main->addWidget(top);
    bottomTabs_ = new QTabWidget(this);
    bottomTabs_->setObjectName("bottomTabs");
    bottomTabs_->addTab(log_, tr("Event log"));
    bottomTabs_->addTab(alarms_, tr("Alarms"));
    bottomTabs_->addTab(devices_, tr("Devices"));
    main->addWidget(bottomTabs_);
    main->setStretchFactor(0, 4);
    main->setStretchFactor(1, 1);
    main->setSizes({800, 140});
    // Nothing in the forms, views or tabs may widen the window: a line no layout can wrap (a
    // bus failure naming every node, a long path) once made its minimum 1855 px and pushed the
    // operator column with the E-STOP off a maximised screen. Ignored: the splitter's minimum
    // is kMinWorkAreaWidth whatever it holds; what does not fit is clipped or elided there.
    main->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    main->setMinimumWidth(kMinWorkAreaWidth);

    auto* central = new QWidget(this);
    auto* h = new QHBoxLayout(central);
    h->setContentsMargins(0, 0, 0, 0);
    h->setSpacing(0);
    h->addWidget(main, 1);
    h->addWidget(column);
    setCentralWidget(central);

    stateLabel_ = new QLabel(tr("Idle"), this);
    stateLabel_->setObjectName("statusState");
    rigLabel_ = new ElidedLabel(tr("no machine yet"), this);
    rigLabel_->setObjectName("statusRig");
    planBar_ = new QProgressBar(this);
    planBar_->setRange(0, 100);
    planBar_->setMaximumWidth(180);
    planBar_->setFormat(tr("planning %p %"));
    planBar_->hide();
    planCancel_ = new QPushButton(tr("Cancel planning"), this);
    planCancel_->hide();
    statusBar()->addWidget(stateLabel_);
    statusBar()->addWidget(rigLabel_, 1);
    cycleLabel_ = new ElidedLabel({}, this);
    cycleLabel_->setObjectName("cycleStats");
    cycleLabel_->setMinimumWidth(120);
    statusBar()->addPermanentWidget(cycleLabel_);
    statusBar()->addPermanentWidget(planBar_);
    statusBar()->addPermanentWidget(planCancel_);
    statusBar()->addPermanentWidget(
        new QLabel(tr("E-STOP: %1 (any field)").arg(ControlPanel::kEStopKey), this));
    // The status bar's messages elide; the bar itself never sets the window's width either.
    statusBar()->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
}

void MainWindow::fitToScreen() {
    // 1600x1000 where the screen has room, else the screen's available area (a 1280x720
    // panel PC opened it at 1440x900, the E-STOP half off screen until maximised).
    QSize size(1600, 1000);
    // Qt's offscreen platform has no screen to fit (a fixed 800x600 stand-in): headless
    // screenshots and tests keep the desktop size.
    const bool realScreen = QGuiApplication::platformName() != QLatin1String("offscreen");
    if (const QScreen* s = screen(); s && realScreen) {
        const QRect room = s->availableGeometry();
        size = size.boundedTo(room.size());
        move(room.topLeft());
    }
    resize(size);
}

void MainWindow::buildMenus() {
    auto* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New..."), QKeySequence::New, this, &MainWindow::newJobFromMenu)
        ->setObjectName("actionNew");
    file->addAction(tr("&Open..."), QKeySequence::Open, this, [this] {
        if (!maybeSave()) return;
        const QString p = QFileDialog::getOpenFileName(
            this, tr("Open job"), QFileInfo(jobsFolder()).isDir() ? jobsFolder() : QString(),
            tr("CutCell jobs (*.json);;All files (*)"));
        if (!p.isEmpty()) openJob(p);
    });
    recentMenu_ = file->addMenu(tr("Open &recent"));
    addImportActions(file, this, [this](const std::string& name) { importFromMenu(name); });
    file->addAction(tr("&Save"), QKeySequence::Save, this, [this] { save(); });
    // Ctrl+Shift+S spelt out: QKeySequence::SaveAs is empty outside GNOME and KDE (seen under
    // openbox: the walkthrough's Ctrl+Shift+S did nothing).
    file->addAction(tr("Save &as..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S), this,
                    [this] { saveAs(); });
    file->addSeparator();
    file->addAction(tr("Export plots as PNG..."), this, [this] {
        const QString p =
            askExport(tr("Export plots"), QStringLiteral("_plots.png"), "PNG (*.png)");
        QString err;
        if (!p.isEmpty() && !plots_->exportPng(p, &err)) log_->add(Severity::Error, err);
    });
    file->addAction(tr("Export plot data as CSV..."), this, [this] {
        const QString p =
            askExport(tr("Export data"), QStringLiteral("_tracking.csv"), "CSV (*.csv)");
        QString err;
        if (!p.isEmpty() && !plots_->exportCsv(p, &err)) log_->add(Severity::Error, err);
    });
    file->addAction(tr("Export alarms as CSV..."), this, [this] {
        const QString p =
            askExport(tr("Export alarms"), QStringLiteral("_alarms.csv"), "CSV (*.csv)");
        QString err;
        if (!p.isEmpty() && !alarms_->exportCsv(p, &err)) log_->add(Severity::Error, err);
    });
    addCutExportMenu(file, this, editor_, log_, [this] { return document_->path(); });
    plots_->setSavePathAsker(
        [this](const QString& title, const QString& tail, const QString& filter) {
            return askExport(title, tail, filter);
        });
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    addLanguageMenu(menuBar(), this,
                    [this](const QString& code) { emit languageChangeRequested(code); });
    addHelpMenu(menuBar(), this);
}

MainWindow::Carry MainWindow::carry() const {
    const EngineState s = run_->bridge()->state();
    return {editor_->job(), document_->path(), document_->modified(),
            params_->tabs()->currentIndex(),
            s == EngineState::Ready || s == EngineState::Completed};
}

void MainWindow::takeOver(const Carry& carry) {
    document_->adopt(carry.job, carry.path, carry.modified);
    params_->tabs()->setCurrentIndex(carry.tab);
}

void MainWindow::addBottomTab(QWidget* tab, const QString& title) {
    bottomTabs_->addTab(tab, title);
}

void MainWindow::addStatusPanel(QWidget* panel) {
    statusLayout_->insertWidget(0, panel);
}

bool MainWindow::canRebuild(QString* why) const {
    const EngineState s = run_->bridge()->state();
    switch (s) {
    case EngineState::Idle:
    case EngineState::Ready:
    case EngineState::Completed:
        return true;
    case EngineState::EmergencyStop:
    case EngineState::Fault:
        *why = tr("clear the %1 first (Release E-STOP, Reset)").arg(stateWord(s));
        return false;
    default:
        *why = tr("the machine is moving (%1): stop it first").arg(stateWord(s));
        return false;
    }
}

QString MainWindow::languageName() const {
    for (const GuiLanguage& l : guiLanguages())
        if (l.code == shownLanguage()) return l.nativeName;
    return shownLanguage();
}

void MainWindow::connectRun() {
    connect(controls_, &ControlPanel::emergencyStopRequested, run_, &RunController::emergencyStop);
    connect(controls_, &ControlPanel::enableRequested, run_, &RunController::enable);
    connect(controls_, &ControlPanel::homeRequested, run_, &RunController::home);
    connect(controls_, &ControlPanel::startRequested, run_, &RunController::start);
    connect(controls_, &ControlPanel::feedHoldRequested, run_, &RunController::feedHold);
    connect(controls_, &ControlPanel::resumeRequested, run_, &RunController::resume);
    connect(controls_, &ControlPanel::abortRequested, run_, &RunController::abort);
    connect(controls_, &ControlPanel::resetRequested, run_, &RunController::reset);
    connect(controls_, &ControlPanel::releaseEStopRequested, run_,
            &RunController::releaseEmergencyStop);
    connect(run_, &RunController::eStopPressedChanged, controls_, &ControlPanel::setEStopPressed);
    connect(run_, &RunController::runStarting, this, [this] {
        // The previous run's data goes at Start, whoever started it (button, key, auto run).
        plots_->clear();
        progress_->beginRun();
        recovery_->setStopPoint(std::nullopt); // a stop of this run will bring a new one
        cell_->setStopMark(-1);
        if (controls_->overridePercent() != 100)
            log_->add(Severity::Warning, tr("This run starts at a speed override of %1 %.")
                                             .arg(controls_->overridePercent()));
    });
    connect(run_, &RunController::runStopped, this, &MainWindow::onRunStopped);
    connect(editor_, &JobEditor::jobReset, this, [this] { // another job: its runs are not ours
        plots_->clear();
        cell_->setStopMark(-1);
        showMachineTerms();
    });
    showMachineTerms();
    connect(run_, &RunController::stopPointChanged, this,
            [this](const cutcell::RunStopPoint& stop) {
                recovery_->setStopPoint(stop);
                progress_->setStopPoint(stop);
                cell_->setStopMark(stop.progress);
            });
    connect(run_, &RunController::programLoaded, recovery_, &RecoveryPanel::setProgram);
    connect(recovery_, &RecoveryPanel::startFromRequested, run_, &RunController::startFrom);
    connect(run_, &RunController::unconfirmedPartChanged, recovery_,
            &RecoveryPanel::setUnconfirmedPart);
    connect(recovery_, &RecoveryPanel::partConfirmed, run_, &RunController::confirmPart);
    connect(run_, &RunController::countersChanged, progress_, &ProgressPanel::setCycleFigures);
    connect(run_, &RunController::programLoaded, this,
            [this](std::shared_ptr<const cutcell::MotionProgram> program) {
                const MachineUi* machine = run_->programMachine();
                dro_->setProgram(program, machine ? machine->axes() : std::vector<AxisLabel>{});
                if (program && !program->spline.empty())
                    progress_->setApproachTarget(program->spline.evaluate(0).q,
                                                 program->axis_count);
                if (!program) return;
                progress_->setProgram(program->terms, program->length_mm);
                alarms_->setTerms(program->terms);
                lamps_->setToolName(toolWord(program->terms));
                cell_->setToolName(toolWord(program->terms));
            });
    connect(dro_, &DroPanel::jogRequested, run_, &RunController::jog);
    connect(dro_, &DroPanel::jogContinuousRequested, run_, &RunController::jogContinuous);
    connect(dro_, &DroPanel::jogStopRequested, run_, &RunController::stopJog);
    connect(alarms_, &AlarmPanel::raised, this, [this] { bottomTabs_->setCurrentWidget(alarms_); });
    connect(alarms_, &AlarmPanel::changed, this, [this](int active, int) {
        bottomTabs_->setTabText(bottomTabs_->indexOf(alarms_),
                                active ? tr("Alarms (%1)").arg(active) : tr("Alarms"));
    });
    connect(controls_, &ControlPanel::overrideChanged, run_, &RunController::setOverride);
    connect(run_, &RunController::startBlockedChanged, controls_, &ControlPanel::setStartBlocked);
    controls_->setStartBlocked(run_->startBlockedReason());
    connect(run_, &RunController::message, log_,
            [this](Severity s, const QString& m) { log_->add(s, m); });
    connect(run_, &RunController::rigChanged, rigLabel_, &ElidedLabel::setFullText);
    connect(run_, &RunController::linkChanged, bus_, &BusPanel::setLink);
    connect(bus_, &BusPanel::reconnectRequested, run_, &RunController::reconnect);
    // The device panel at ~5 Hz from the rig (a short mutex in the CAN master, no bus wait).
    deviceTimer_ = new QTimer(this);
    deviceTimer_->setInterval(200);
    connect(deviceTimer_, &QTimer::timeout, this, &MainWindow::refreshDevicePanel);
    deviceTimer_->start();
    connect(devices_, &cutcell::ui::DevicePanel::faultResetRequested, this, [this] {
        if (EngineRig* rig = run_->rig()) rig->faultReset(0);
        run_->reset();
    });
    connect(run_, &RunController::planStarted, this, [this] {
        planBar_->setValue(0);
        planBar_->show();
        planCancel_->show();
    });
    connect(run_, &RunController::planProgress, this,
            [this](double f) { planBar_->setValue(static_cast<int>(f * 100)); });
    connect(run_->planner(), &PlanWorker::planned, this, [this] {
        planBar_->hide();
        planCancel_->hide();
    });
    connect(run_->planner(), &PlanWorker::cancelled, planBar_, &QWidget::hide);
    connect(run_->planner(), &PlanWorker::cancelled, planCancel_, &QWidget::hide);
    connect(run_->planner(), &PlanWorker::failed, planBar_, &QWidget::hide);
    connect(run_->planner(), &PlanWorker::failed, planCancel_, &QWidget::hide);
    connect(planCancel_, &QPushButton::clicked, run_, &RunController::cancelPlanning);
    connect(run_, &RunController::planChanged, this,
            [this](std::shared_ptr<const cutcell::MachinePlan> plan, const cutcell::Job& job) {
                adaptViewsToPlan(plan, job, cell_, plots_, progress_);
            });
    auto* bridge = run_->bridge();
    connect(bridge, &EngineBridge::samples, this, &MainWindow::onSamples);
    connect(bridge, &EngineBridge::event, log_, &EventLogPanel::addEngineEvent);
    connect(bridge, &EngineBridge::event, alarms_, &AlarmPanel::addEngineEvent);
    connect(bridge, &EngineBridge::event, this, [this](const cutcell::EngineEvent& e) {
        // The run's log folder gets the run's alarms (alarms.json beside summary.json).
        if (e.kind != cutcell::EventKind::RunEnded || !run_->rig()) return;
        alarms_->setRunDirectory(e.run_id,
                                 QString::fromStdString(run_->rig()->engine().lastRunDirectory()));
    });
    connect(bridge, &EngineBridge::stateChanged, this, &MainWindow::onState);
    connect(bridge, &EngineBridge::cycleStats, this, [this](const cutcell::CycleStats& c) {
        QString text = tr("cycle %1 ms, jitter p99 %2 us, overruns %3")
                           .arg(shownSignificant(c.period_s * 1000.0, 3))
                           .arg(shownNumber(c.jitter_us_p99, 0))
                           .arg(c.overruns);
        if (c.estops_measured > 0)
            text += tr(", E-STOP latency %1 us").arg(shownNumber(c.last_estop_latency_us, 0));
        cycleLabel_->setFullText(text);
    });
}

void MainWindow::onSamples(const std::vector<cutcell::TelemetrySample>& batch) {
    const auto& last = batch.back();
    plots_->append(batch);
    // One display frame (a single window composition) at most every kDisplayFrameMs, at once
    // when the state, the torch or the end of the path changes. With the 3D view's
    // QOpenGLWidget in the window every composition redraws the whole window through OpenGL
    // (10-40 ms with llvmpipe): one per 33 ms telemetry tick saturated the GUI thread.
    const bool due = !sinceDisplayFrame_.isValid() ||
                     sinceDisplayFrame_.elapsed() >= kDisplayFrameMs || last.state != shownState_ ||
                     last.torch_on != shownTorch_ || last.progress >= 1.0;
    if (!due) return;
    sinceDisplayFrame_.start();
    shownState_ = last.state;
    shownTorch_ = last.torch_on;
    plots_->redraw();
    progress_->setSample(last);
    dro_->setSample(last);
    cell_->setSample(last);
    lamps_->setTorch(last.torch_on);
    controls_->setState(last.state, last.homed);
    recovery_->setState(last.state, last.homed);
}

void MainWindow::onState(EngineState s) {
    lamps_->setState(s);
    dro_->setState(s);
    alarms_->setState(s);
    controls_->setState(s, run_->bridge()->last().homed);
    recovery_->setState(s, run_->bridge()->last().homed);
    plots_->setPaused(s == EngineState::Paused);
    stateLabel_->setText(stateWord(s));
    if (s == EngineState::EmergencyStop || s == EngineState::Fault) lamps_->setTorch(false);
    const bool locked = s == EngineState::Running || s == EngineState::Paused ||
                        s == EngineState::Homing || s == EngineState::Jogging;
    params_->setEditingLocked(locked, tr("Parameters are locked while the machine moves."));
}

void MainWindow::refreshTitle() {
    setWindowTitle(tr("%1[*] - CutCell").arg(document_->displayName()));
    setWindowModified(document_->modified());
}

void MainWindow::refreshRecentMenu() {
    recentMenu_->clear();
    const QStringList files = document_->recentFiles();
    for (const QString& f : files)
        recentMenu_
            ->addAction(QFileInfo(f).fileName(), this,
                        [this, f] {
                            if (maybeSave()) openJob(f);
                        })
            ->setToolTip(f);
    recentMenu_->setEnabled(!files.isEmpty());
    if (!files.isEmpty()) {
        recentMenu_->addSeparator();
        recentMenu_->addAction(tr("Clear list"), document_, &JobDocument::clearRecentFiles);
    }
}

void MainWindow::onRunStopped(EngineState state, const QString& how) {
    (void)state;
    progress_->markStopped(how);
    // A stop is a deliberate break: the next run does not inherit a forgotten 150 %.
    if (controls_->overridePercent() != 100) {
        log_->add(Severity::Warning, tr("Speed override set back to 100 % after the %1 (was %2 %).")
                                         .arg(how)
                                         .arg(controls_->overridePercent()));
        controls_->setOverridePercent(100);
    }
}

void MainWindow::showFileError(const QString& title, const QString& message) {
    if (errorPrompt_)
        errorPrompt_(title, message);
    else if (isVisible())
        QMessageBox::critical(this, title, message);
}

bool MainWindow::openJob(const QString& path, QString* error) {
    QString err;
    if (!document_->open(path, &err)) {
        log_->add(Severity::Error, err);
        showFileError(tr("Cannot open the job"), err);
        if (error) *error = err;
        return false;
    }
    log_->add(Severity::Info, tr("Opened %1").arg(document_->path()));
    return true;
}

bool MainWindow::importJob(const std::string& importer, const QString& path, QString* error) {
    ImportOutcome imported;
    QString err;
    if (!importJobFile(importer, path, &imported, &err)) {
        log_->add(Severity::Error, err);
        showFileError(tr("Cannot import the file"), err);
        if (error) *error = err;
        return false;
    }
    if (QString why; !document_->newJob(imported.job, &why)) {
        err = tr("Cannot import %1: %2").arg(path, why);
        log_->add(Severity::Error, err);
        showFileError(tr("Cannot import the file"), err);
        if (error) *error = err;
        return false;
    }
    const QString file = QFileInfo(path).fileName();
    for (const QString& line : imported.report)
        log_->add(Severity::Warning, QStringLiteral("%1: %2").arg(file, line));
    log_->add(Severity::Info, tr("Imported %1 as a new job (%2 report lines); save it to keep it.")
                                  .arg(path)
                                  .arg(imported.report.size()));
    if (importReportPrompt_)
        importReportPrompt_(path, imported.report);
    else if (isVisible())
        showImportReport(this, path, imported.report);
    return true;
}

bool MainWindow::importJobs(const std::string& importer, const QStringList& paths,
                            const QString& folder, QString* error) {
    cutcell::JobImporter i;
    QString err;
    cutcell::ImportBatch batch;
    try {
        if (!cutcell::findJobImporter(importer, &i))
            throw std::runtime_error("no importer \"" + importer + "\"");
        std::vector<std::string> files;
        for (const QString& p : paths)
            files.push_back(p.toStdString());
        batch = cutcell::importBatch(i, files, folder.toStdString());
    } catch (const std::exception& e) {
        err = tr("Cannot import the files: %1").arg(QString::fromUtf8(e.what()));
        log_->add(Severity::Error, err);
        showFileError(tr("Cannot import the files"), err);
        if (error) *error = err;
        return false;
    }
    QString first;
    for (const cutcell::ImportBatchRow& r : batch.rows) {
        const QString file = QString::fromStdString(r.file);
        if (!r.imported) {
            log_->add(Severity::Error,
                      tr("%1: refused: %2").arg(file, QString::fromStdString(r.reason)));
            continue;
        }
        for (const std::string& line : r.report)
            log_->add(Severity::Warning,
                      QStringLiteral("%1: %2").arg(file, QString::fromStdString(line)));
        if (first.isEmpty()) first = QDir(folder).filePath(QString::fromStdString(r.job));
    }
    log_->add(Severity::Info, tr("Imported %1 of %2 file(s) into %3 (import-report.csv)")
                                  .arg(batch.rows.size() - static_cast<size_t>(batch.refused))
                                  .arg(batch.rows.size())
                                  .arg(folder));
    if (importBatchPrompt_)
        importBatchPrompt_(batch);
    else if (isVisible())
        showImportBatchReport(this, batch, folder);
    if (first.isEmpty()) {
        if (error) *error = tr("No file was imported.");
        return false;
    }
    return openJob(first, error);
}

void MainWindow::importFromMenu(const std::string& importer) {
    if (!maybeSave()) return;
    cutcell::JobImporter i;
    if (!cutcell::findJobImporter(importer, &i)) return;
    const QStringList paths = QFileDialog::getOpenFileNames(
        this, tr("Import %1").arg(QString::fromStdString(i.title)), {}, importFileFilter(i));
    if (paths.size() == 1) importJob(importer, paths.front());
    if (paths.size() < 2) return;
    const QString folder = importFolderPrompt_
                               ? importFolderPrompt_()
                               : QFileDialog::getExistingDirectory(
                                     this, tr("Folder for the %1 imported jobs").arg(paths.size()),
                                     QFileInfo(paths.front()).absolutePath());
    if (!folder.isEmpty()) importJobs(importer, paths, folder);
}

void MainWindow::newJobFromMenu() {
    if (!maybeSave()) return;
    const std::string current = editor_->job().machine;
    const std::string id = machinePrompt_ ? machinePrompt_() : askMachine(this, current);
    if (!id.empty()) newJob(id);
}

bool MainWindow::newJob(const std::string& machineId) {
    const MachineUi* machine = findMachineUi(machineId);
    if (!machine) {
        log_->add(Severity::Error,
                  tr("No machine \"%1\" in this build.").arg(QString::fromStdString(machineId)));
        return false;
    }
    try {
        if (QString why; !document_->newJob(machine->defaultJob(), &why)) {
            log_->add(Severity::Error, tr("No new job for the %1: %2").arg(machine->title(), why));
            return false;
        }
    } catch (const std::exception& e) {
        log_->add(
            Severity::Error,
            tr("No default job for the %1: %2").arg(machine->title(), QString::fromUtf8(e.what())));
        return false;
    }
    log_->add(Severity::Info, tr("New job for the %1.").arg(machine->title()));
    return true;
}

bool MainWindow::save() {
    if (document_->path().isEmpty()) return saveAs();
    if (mustNotOverwrite(document_->path())) {
        log_->add(Severity::Info,
                  tr("%1 is an example shipped with CutCell or a read-only file: Save writes a "
                     "copy (Save As).")
                      .arg(document_->path()));
        return saveAs();
    }
    QString err;
    if (!document_->save(&err)) {
        log_->add(Severity::Error, err);
        showFileError(tr("Cannot save the job"), err);
        return false;
    }
    log_->add(Severity::Info, tr("Saved %1").arg(document_->path()));
    return true;
}

bool MainWindow::saveAs(const QString& path) {
    QString p = path;
    if (p.isEmpty())
        p = askSavePath(
            this, SaveKind::Job, tr("Save job"),
            proposedJobPath(document_->path(), QString::fromStdString(editor_->job().name)),
            tr("CutCell jobs (*.json)"));
    if (p.isEmpty()) return false;
    QString err;
    if (!document_->saveAs(p, &err)) {
        log_->add(Severity::Error, err);
        showFileError(tr("Cannot save the job"), err);
        return false;
    }
    log_->add(Severity::Info, tr("Saved %1").arg(document_->path()));
    return true;
}

QString MainWindow::askExport(const QString& title, const QString& tail, const QString& filter) {
    return askSavePath(
        this, SaveKind::Export, title,
        proposedExportPath(document_->path(), QString::fromStdString(editor_->job().name), tail),
        filter);
}

bool MainWindow::maybeSave() {
    if (!document_->modified()) return true;
    const int answer =
        savePrompt_
            ? savePrompt_()
            : QMessageBox::warning(this, tr("Unsaved changes"),
                                   tr("The job \"%1\" has unsaved changes. Save them?")
                                       .arg(document_->displayName()),
                                   QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                   QMessageBox::Save);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::showEvent(QShowEvent* e) {
    QMainWindow::showEvent(e);
    if (splitSet_) return;
    splitSet_ = true;
    // The first show decides the split for the window's real size (1280x720 as well as
    // 1600x1000): the 3D view gets most of the centre, the log a fifth of the height.
    auto* main = findChild<QSplitter*>(QStringLiteral("mainSplitter"));
    auto* centre = findChild<QSplitter*>(QStringLiteral("centreSplitter"));
    if (main) main->setSizes({main->height() * 4 / 5, main->height() / 5});
    if (centre) centre->setSizes({centre->height() * 3 / 5, centre->height() * 2 / 5});
}

void MainWindow::closeEvent(QCloseEvent* e) {
    const auto s = run_->bridge()->state();
    if (s == EngineState::Running || s == EngineState::Paused || s == EngineState::Homing) {
        const auto answer = QMessageBox::warning(
            this, tr("Machine in motion"),
            tr("The machine is %1. Quitting stops it at once (emergency stop). Quit?")
                .arg(stateWord(s)),
            QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
        if (answer != QMessageBox::Yes) {
            e->ignore();
            return;
        }
        run_->emergencyStop();
    }
    if (maybeSave())
        e->accept();
    else
        e->ignore();
}

void MainWindow::refreshDevicePanel() {
    cutcell::ui::DevicePanelSnapshot snapshot; // can = false: simulated in-process drives
    if (EngineRig* rig = run_->rig()) rig->deviceSnapshot(snapshot);
    devices_->setSnapshot(snapshot);
    bus_->setSnapshot(snapshot);
    // A bus just came up: show it (the operator can switch back to the log).
    if (snapshot.can && !showingBus_) bottomTabs_->setCurrentWidget(devices_);
    showingBus_ = snapshot.can;
}

} // namespace CutCell::ui
