#include "shopfloor_station.h"

#include "production_record.h"
#include "shopfloor_settings.h"
#include "station_access.h"

#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/process/consumable_counters.h"
#include "core/shopfloor/telemetry_snapshot.h"
#include "devices/shopfloor/mosquitto_link.h"
#include "ui/access_control.h"
#include "ui/engine_bridge.h"
#include "ui/forms/job_editor.h"
#include "ui/job_document.h"
#include "ui/job_queue.h"
#include "ui/main_window.h"
#include "ui/panels/alarm_panel.h"
#include "ui/panels/job_queue_panel.h"
#include "ui/run_controller.h"

#include <QCoreApplication>
#include <QLabel>
#include <QPointer>
#include <QStatusBar>
#include <QTimer>

#include <cstdlib>
#include <filesystem>
#include <memory>

namespace cutcell::app {
namespace {

struct Shopfloor {
    std::unique_ptr<CutCell::ui::JobQueue> queue;
    StationCommands commands;
    std::unique_ptr<shopfloor::MosquittoLink> link;
    QPointer<CutCell::ui::MainWindow> window; // the window the commands act on
    std::string given;                        // openShopfloor's argument ("", "off" or a file)
};

Shopfloor& station() {
    static Shopfloor s;
    return s;
}

std::string defaultConfigPath() {
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    const std::string base = xdg && *xdg ? xdg : std::string(home ? home : ".") + "/.config";
    return base + "/cutcell/shopfloor.json";
}

// The window's state now, as the shop floor sees it.
} // namespace

shopfloor::CellSnapshot stationSnapshot(CutCell::ui::MainWindow& w) {
    shopfloor::CellSnapshot s;
    const Job& job = w.editor()->job();
    if (const MachineModule* module = findMachine(job.machine))
        s = shopfloor::cellSnapshotOf(job, *module);
    s.job_name = job.name;
    CutCell::ui::EngineBridge* bridge = w.run()->bridge();
    if (bridge->hasSample()) shopfloor::applyTelemetry(s, bridge->last());
    s.state = toString(bridge->state());
    s.pieces_made = static_cast<std::uint64_t>(std::max(0, w.run()->partsCompleted()));
    s.made = std::to_string(s.pieces_made) + " completed since the job was opened";
    for (const CutCell::ui::Alarm& a : w.alarms()->alarms())
        if (a.active) s.alarms.push_back((a.source + ": " + a.logged).toStdString());
    s.last_run = lastRunFigures();
    s.queue_length = static_cast<std::uint32_t>(stationJobQueue()->size());
    if (job.process.used)
        if (ConsumableLedger* ledger = consumableLedger()) try {
                const cutcell::ConsumableCounters c =
                    ledger->current({job.process.process, job.process.consumable});
                s.consumables = shopfloor::ConsumableCounters{static_cast<std::uint64_t>(c.pierces),
                                                              c.arcOnS()};
            } catch (const std::exception&) {
                // The record cannot be read now: the counters are left out, not guessed.
            }
    return s;
}

namespace {

// The link closed and opened again as it was given (a saved file takes effect; "off" stays off).
std::string restartShopfloor() {
    closeShopfloor();
    return openShopfloor(station().given);
}

// "Link settings…": allowed by the station's users (re-checked at each log-in and log-out),
// opens the settings of the file the station uses.
void wireLinkSettings(CutCell::ui::JobQueuePanel* panel, CutCell::ui::MainWindow& window) {
    const auto recheck = [panel] {
        const QString why = shopfloorSettingsLockReason(stationAccess());
        panel->setSettingsAllowed(why.isEmpty(), why);
    };
    if (CutCell::ui::AccessControl* access = stationAccess())
        QObject::connect(access, &CutCell::ui::AccessControl::changed, panel, recheck);
    recheck();
    QObject::connect(panel, &CutCell::ui::JobQueuePanel::settingsRequested, &window,
                     [panel, &window] {
                         if (!shopfloorSettingsLockReason(stationAccess()).isEmpty()) return;
                         auto* dialog = new ShopfloorSettingsDialog(
                             shopfloorSettingsPath(), stationAccess(), &restartShopfloor, &window);
                         dialog->setAttribute(Qt::WA_DeleteOnClose);
                         QObject::connect(dialog, &ShopfloorSettingsDialog::saved, panel,
                                          &CutCell::ui::JobQueuePanel::setLinkText);
                         dialog->open();
                     });
}

} // namespace

CutCell::ui::JobQueue* stationJobQueue() {
    auto& q = station().queue;
    if (!q) q = std::make_unique<CutCell::ui::JobQueue>();
    return q.get();
}

std::string StationCommands::queueJob(const std::string& jobText, const std::string& source) {
    Job job;
    try {
        job = parseJob(jobText);
    } catch (const std::exception& e) {
        return e.what();
    }
    if (const auto issues = validateJob(job); !issues.empty())
        return issues.front().message; // it names the key, the value, the unit and the limit
    CutCell::ui::JobQueue* queue = stationJobQueue();
    const QString from = QString::fromStdString("shop floor (" + source + ")");
    QMetaObject::invokeMethod(
        queue, [queue, job, from] { queue->add(job, from); }, Qt::QueuedConnection);
    return {};
}

void StationCommands::feedHold() {
    // A feed hold from the network is always allowed; it acts like the operator's button.
    QMetaObject::invokeMethod(
        stationJobQueue(),
        [] {
            if (CutCell::ui::MainWindow* w = station().window) w->run()->feedHold();
        },
        Qt::QueuedConnection);
}

void StationCommands::clearQueue() {
    CutCell::ui::JobQueue* queue = stationJobQueue();
    QMetaObject::invokeMethod(
        queue, [queue] { queue->clear(); }, Qt::QueuedConnection);
}

std::string openShopfloor(const std::string& configPath) {
    Shopfloor& s = station();
    stationJobQueue(); // made on the GUI thread, before the link's thread can post to it
    s.given = configPath;
    if (configPath == "off") return "shop floor: off (--shopfloor off)";
    const std::string path = configPath.empty() ? defaultConfigPath() : configPath;
    if (configPath.empty() && !std::filesystem::exists(path))
        return "shop floor: off (no " + path + "; --shopfloor FILE)";
    shopfloor::ShopfloorConfig config;
    try {
        config = shopfloor::loadShopfloorConfig(path);
    } catch (const std::exception& e) {
        return std::string("shop floor: not connected: ") + e.what();
    }
    if (!config.enabled) return "shop floor: off (" + path + " says \"enabled\": false)";
    s.link = std::make_unique<shopfloor::MosquittoLink>(config, &s.commands);
    std::string error;
    if (!s.link->start(&error)) {
        s.link.reset();
        return "shop floor: not connected: " + error;
    }
    return "shop floor: " + config.host + ":" + std::to_string(config.port) + " as spBv1.0/" +
           config.group_id + "/.../" + config.edge_node_id;
}

void closeShopfloor() {
    Shopfloor& s = station();
    if (s.link) s.link->stop();
    s.link.reset();
}

std::string shopfloorSettingsPath() {
    const std::string& given = station().given;
    return given.empty() || given == "off" ? defaultConfigPath() : given;
}

void attachShopfloor(CutCell::ui::MainWindow& window) {
    Shopfloor& s = station();
    s.window = &window;
    auto* panel = new CutCell::ui::JobQueuePanel(stationJobQueue(), window.document(), &window);
    window.addBottomTab(panel, CutCell::ui::JobQueuePanel::tr("Job queue"));
    wireLinkSettings(panel, window);
    auto* linkLabel = new QLabel(&window);
    linkLabel->setObjectName("shopfloorLink");
    window.statusBar()->addPermanentWidget(linkLabel);
    auto* timer = new QTimer(&window);
    timer->setInterval(100);
    QObject::connect(timer, &QTimer::timeout, &window, [&window, panel, linkLabel] {
        Shopfloor& st = station();
        if (!st.link) {
            linkLabel->setText(CutCell::ui::JobQueuePanel::tr("Shop floor: off"));
            return;
        }
        st.link->submit(stationSnapshot(window)); // returns at once (the node diffs and queues)
        const QString text = CutCell::ui::JobQueuePanel::tr("Shop floor: %1")
                                 .arg(QString::fromStdString(st.link->status().text));
        linkLabel->setText(text);
        panel->setLinkText(text);
    });
    timer->start();
}

} // namespace cutcell::app
