#include "station_access.h"

#include "production_record.h"

#include "core/machine/machine_registry.h"
#include "devices/record/audit_trail.h"
#include "devices/record/run_record_store.h"
#include "devices/record/user_directory.h"
#include "ui/access_control.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/main_window.h"
#include "ui/panels/consumables_panel.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/history_panel.h"
#include "ui/panels/login_panel.h"
#include "ui/run_controller.h"

#include <QTimer>

#include <memory>

namespace cutcell::app {
namespace {

struct Station {
    std::unique_ptr<AuditTrail> trail;
    std::unique_ptr<UserDirectory> users;
    std::unique_ptr<CutCell::ui::AccessControl> access;
};

Station& station() {
    static Station s;
    return s;
}

} // namespace

std::string openStationAccess(const std::string& where) {
    closeStationAccess();
    Station& s = station();
    std::string line, unavailable;
    if (where != "off") {
        const std::string path = where.empty() ? defaultProductionDbPath() : where;
        try {
            s.trail = std::make_unique<AuditTrail>(path);
            s.users = std::make_unique<UserDirectory>(path, *s.trail);
            const std::string& in = s.trail->where(); // no password
            line = s.users->hasUsers()
                       ? "users: log in at the operator column (" + in + ")"
                       : "users: none in " + in + ": single-user mode (cutcell-cli users add)";
        } catch (const RecordError& e) {
            s.users.reset();
            s.trail.reset();
            unavailable = e.what();
            line = std::string("users and audit trail cannot be read: the fields are locked (") +
                   e.what() + "; --record off runs without users)";
        }
    } else {
        line = "users: single-user mode, no audit trail (--record off)";
    }
    s.access = std::make_unique<CutCell::ui::AccessControl>(
        s.users.get(), s.trail.get(), QString::fromStdString(RunRecordStore::desktopUser()));
    if (!unavailable.empty()) s.access->setUnavailable(QString::fromStdString(unavailable));
    return line;
}

CutCell::ui::AccessControl* stationAccess() {
    return station().access.get();
}

void closeStationAccess() {
    Station& s = station();
    s.access.reset();
    s.users.reset();
    s.trail.reset();
}

void attachStationAccess(CutCell::ui::MainWindow& window) {
    using namespace CutCell::ui;
    AccessControl* access = stationAccess();
    if (!access) return;
    window.addStatusPanel(new LoginPanel(access, &window));
    window.addBottomTab(new HistoryPanel(productionRecordFile(), &window),
                        HistoryPanel::tr("History"));
    window.addBottomTab(
        new ConsumablesPanel(
            consumableLedger(), window.editor(), [access] { return access->user(); }, &window),
        ConsumablesPanel::tr("Consumables"));
    JobEditor* editor = window.editor();
    editor->setGate([access, editor](const std::string& key) {
        return access->lockReason(key, findMachine(editor->job().machine));
    });
    editor->setOpenGate([access](const cutcell::Job& from, const cutcell::Job& to) {
        return access->openLockReason(from, to);
    });
    window.run()->setRunGate([access] { return access->runLockReason(); });
    QObject::connect(access, &AccessControl::changed, &window, [&window] {
        window.parameters()->applyAccess();
        window.run()->recheckStart();
        if (auto* record = productionRecordFile())
            record->setOperator(stationAccess()->user().toStdString());
    });
    window.parameters()->applyAccess();
    // A value typed digit by digit is one change: the first old value to the last new one,
    // written when another field changes, 2 s after the last keystroke, or at a log-out.
    struct Pending {
        QString key, was, now;
    };
    auto pending = std::make_shared<Pending>();
    auto* typing = new QTimer(&window);
    typing->setSingleShot(true);
    typing->setInterval(2000);
    const auto flush = [access, pending] {
        if (pending->key.isEmpty()) return;
        if (pending->was != pending->now)
            access->audit(audit_event::kParameterChanged, pending->key, pending->was, pending->now);
        pending->key.clear();
    };
    QObject::connect(editor, &JobEditor::parameterChanged, typing,
                     [=](const QString& key, const QString& was, const QString& now) {
                         if (key != pending->key) {
                             flush();
                             *pending = {key, was, now};
                         }
                         pending->now = now;
                         typing->start();
                     });
    QObject::connect(typing, &QTimer::timeout, access, flush);
    QObject::connect(access, &AccessControl::aboutToLogOut, typing, flush);
    QObject::connect(&window, &QObject::destroyed, access, flush);
    ControlPanel* controls = window.controls();
    QObject::connect(controls, &ControlPanel::emergencyStopRequested, access,
                     [access] { access->audit(audit_event::kEmergencyStop); });
    QObject::connect(controls, &ControlPanel::resetRequested, access,
                     [access] { access->audit(audit_event::kReset); });
    QObject::connect(window.run(), &RunController::recoveryStarting, access, [access](double t) {
        access->audit(audit_event::kRecovery, "path_time_s", {}, QString::number(t, 'f', 3), "s");
    });
    // An override is dragged through many values: one event per settled change.
    auto* settle = new QTimer(&window);
    settle->setSingleShot(true);
    settle->setInterval(1000);
    auto from = std::make_shared<double>(-1), to = std::make_shared<double>(-1);
    QObject::connect(controls, &ControlPanel::overrideChanged, settle, [=](double f) {
        if (*from < 0) *from = *to < 0 ? f : *to;
        *to = f;
        settle->start();
    });
    QObject::connect(settle, &QTimer::timeout, access, [=] {
        if (*from >= 0 && *from != *to)
            access->audit(audit_event::kOverrideChanged, "override",
                          QString::number(*from * 100, 'f', 0), QString::number(*to * 100, 'f', 0),
                          "%");
        *from = -1;
    });
}

} // namespace cutcell::app
