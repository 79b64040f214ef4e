#pragma once
// The operator station's main window. It only lays out and connects the parts: parameter
// forms (ParameterTabs/JobEditor), the job file (JobDocument), the run (RunController with
// its EngineBridge and PlanWorker), the control panel with the EMERGENCY STOP, lamps,
// progress, 3D view, plots and the event log. No maths and no device I/O here.
//
// Threading contract: GUI thread only.
#include "ui/engine_rig.h"

#include <QElapsedTimer>
#include <QMainWindow>

#include <functional>
#include <string>

namespace cutcell {
struct ImportBatch;
}

class QLabel;
class QTabWidget;
class QTimer;
class QMenu;
class QProgressBar;
class QPushButton;
class QVBoxLayout;

namespace cutcell::ui {
class DevicePanel;
}

namespace CutCell::ui {

class AlarmPanel;
class BusPanel;
class RecoveryPanel;
class CellViewPanel;
class DroPanel;
class ControlPanel;
class EventLogPanel;
class JobDocument;
class JobEditor;
class ParameterTabs;
class PlotsPanel;
class ProgressPanel;
class RunController;
class StateLamps;
class ElidedLabel;

class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    explicit MainWindow(EngineRigFactory factory, QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a job file; on failure the message is logged and returned.
    bool openJob(const QString& path, QString* error = nullptr);
    // A new job from that machine's default job; false (logged) for an unknown machine.
    bool newJob(const std::string& machineId);
    bool save();
    bool saveAs(const QString& path = {});
    // Asks whether to save unsaved changes; false when the user cancels.
    bool maybeSave();
    // Replaces the Save/Discard/Cancel dialog (tests): returns a QMessageBox::StandardButton.
    void setSavePrompt(std::function<int()> prompt) { savePrompt_ = std::move(prompt); }
    // Replaces File -> New's machine list (tests): returns a machine id, empty = cancel.
    void setMachinePrompt(std::function<std::string()> prompt) {
        machinePrompt_ = std::move(prompt);
    }
    // File -> New as the menu does it: unsaved changes, the machine, the new job.
    void newJobFromMenu();
    // File -> Import <format>: the file through that importer as a new document; its report
    // lines go to the event log (warnings) and, while the window is on screen, a dialog.
    bool importJob(const std::string& importer, const QString& path, QString* error = nullptr);
    // Several files at once: one job per file into `folder` (and its import-report.csv), the
    // table in a dialog (or the batch prompt), the first imported job opened. False when none
    // was imported or the folder cannot be written (*error says why).
    bool importJobs(const std::string& importer, const QStringList& paths, const QString& folder,
                    QString* error = nullptr);
    // File -> Import <format>: one file or several (a batch asks for the jobs' folder).
    void importFromMenu(const std::string& importer);
    // Replaces the batch's folder question and its table dialog (tests).
    void setImportBatchPrompts(std::function<QString()> folder,
                               std::function<void(const cutcell::ImportBatch&)> report) {
        importFolderPrompt_ = std::move(folder);
        importBatchPrompt_ = std::move(report);
    }
    // Replaces the import report dialog (tests): gets the file and the report lines.
    void setImportReportPrompt(std::function<void(const QString&, const QStringList&)> prompt) {
        importReportPrompt_ = std::move(prompt);
    }
    // Replaces the file error dialog (tests, unattended runs): gets the title and the message.
    // Without it the dialog is shown while the window is on screen (the log always has it).
    void setErrorPrompt(std::function<void(const QString&, const QString&)> prompt) {
        errorPrompt_ = std::move(prompt);
    }

    JobEditor* editor() const { return editor_; }
    JobDocument* document() const { return document_; }
    RunController* run() const { return run_; }
    ParameterTabs* parameters() const { return params_; }
    ControlPanel* controls() const { return controls_; }
    StateLamps* lamps() const { return lamps_; }
    ProgressPanel* progress() const { return progress_; }
    EventLogPanel* eventLog() const { return log_; }
    CellViewPanel* cellView() const { return cell_; }
    PlotsPanel* plots() const { return plots_; }
    cutcell::ui::DevicePanel* devicePanel() const { return devices_; }
    DroPanel* dro() const { return dro_; }
    AlarmPanel* alarms() const { return alarms_; }
    RecoveryPanel* recovery() const { return recovery_; }
    BusPanel* busPanel() const { return bus_; }
    QWidget* operatorColumn() const { return column_; }
    // A panel at the top of the operator column's status part (below E-STOP and the buttons,
    // which stay on screen): the app's log-in panel.
    void addStatusPanel(QWidget* panel);
    // A tab beside the event log, the alarms and the devices: the app's History view.
    void addBottomTab(QWidget* tab, const QString& title);

    // What a rebuilt window (another language, ui/window_host.h) takes over from this one.
    struct Carry {
        cutcell::Job job;
        QString path;
        bool modified = false;
        int tab = 0;                // the parameter tab shown
        bool drivesEnabled = false; // they are disabled by the rebuild
    };
    Carry carry() const;
    void takeOver(const Carry& carry);
    // The window may be rebuilt only with the machine at rest and no alarm latched (an E-STOP
    // or a fault must be cleared where it was raised); otherwise false with the reason.
    bool canRebuild(QString* why) const;
    // The language the window is shown in, as its menu names it ("English", "Deutsch").
    QString languageName() const;

  signals:
    // Language -> a language: the host rebuilds the window in it (ui/window_host.h).
    void languageChangeRequested(const QString& code);

  public:
    // The narrowest the left part (forms, 3D view, plots, log) may become; what it holds may
    // not widen the window beyond it plus the operator column (ui/main_window.cpp).
    static constexpr int kMinWorkAreaWidth = 640;

  protected:
    void closeEvent(QCloseEvent* e) override;
    void showEvent(QShowEvent* e) override;

  private:
    void buildLayout();
    void buildMenus();
    void fitToScreen();
    void connectRun();
    void refreshTitle();
    // The job's machine's words (the tool lamp, the alarms' source) before its first plan.
    void showMachineTerms();
    void refreshRecentMenu();
    void onSamples(const std::vector<cutcell::TelemetrySample>& batch);
    void onState(cutcell::EngineState s);
    void refreshDevicePanel();
    void showFileError(const QString& title, const QString& message);
    // The export dialog on <exports folder>/<job's stem><tail> (ui/file_places.h).
    QString askExport(const QString& title, const QString& tail, const QString& filter);
    void onRunStopped(cutcell::EngineState state, const QString& how);

    JobEditor* editor_;
    JobDocument* document_;
    RunController* run_;
    ParameterTabs* params_ = nullptr;
    ControlPanel* controls_ = nullptr;
    StateLamps* lamps_ = nullptr;
    ProgressPanel* progress_ = nullptr;
    EventLogPanel* log_ = nullptr;
    cutcell::ui::DevicePanel* devices_ = nullptr;
    DroPanel* dro_ = nullptr;
    AlarmPanel* alarms_ = nullptr;
    RecoveryPanel* recovery_ = nullptr;
    BusPanel* bus_ = nullptr;
    QWidget* column_ = nullptr;
    QVBoxLayout* statusLayout_ = nullptr;
    QTimer* deviceTimer_ = nullptr;
    QTabWidget* bottomTabs_ = nullptr; // event log, devices
    bool showingBus_ = false;
    CellViewPanel* cell_ = nullptr;
    PlotsPanel* plots_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QLabel* stateLabel_ = nullptr;
    ElidedLabel* rigLabel_ = nullptr;
    ElidedLabel* cycleLabel_ = nullptr;
    QProgressBar* planBar_ = nullptr;
    QPushButton* planCancel_ = nullptr;
    std::function<int()> savePrompt_;
    std::function<std::string()> machinePrompt_;
    std::function<void(const QString&, const QString&)> errorPrompt_;
    std::function<void(const QString&, const QStringList&)> importReportPrompt_;
    std::function<QString()> importFolderPrompt_;
    std::function<void(const cutcell::ImportBatch&)> importBatchPrompt_;
    // Display frames: the panels follow the telemetry at most every kDisplayFrameMs.
    static constexpr int kDisplayFrameMs = 60;
    QElapsedTimer sinceDisplayFrame_;
    cutcell::EngineState shownState_ = cutcell::EngineState::Idle;
    bool shownTorch_ = false;
    bool splitSet_ = false;
};

} // namespace CutCell::ui
