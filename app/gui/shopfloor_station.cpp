#include "shopfloor_station.h"

#include "production_record.h"

#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/process/consumable_counters.h"
#include "devices/shopfloor/mosquitto_link.h"
#include "ui/engine_bridge.h"
#include "ui/forms/job_editor.h"
#include "ui/job_document.h"
#include "ui/job_queue.h"
#include "ui/main_window.h"
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
shopfloor::CellSnapshot snapshotOf(CutCell::ui::MainWindow& w) {
    shopfloor::CellSnapshot s;
    const Job& job = w.editor()->job();
    const MachineModule* module = findMachine(job.machine);
    if (module) {
        s.machine_id = module->id();
        s.machine_name = module->title();
    }
    s.job_name = job.name;
    CutCell::ui::EngineBridge* bridge = w.run()->bridge();
    s.state = toString(bridge->state());
    if (module)
        for (const AxisInfo& a : module->axes(job))
            s.axes.push_back({a.name, unitSymbol(a.unit), 0, 0});
    if (bridge->hasSample()) {
        const TelemetrySample& t = bridge->last();
        s.progress = t.progress;
        for (std::size_t i = 0; i < s.axes.size() && i < t.axis_count; ++i) {
            const double k = t.units[i] == AxisUnit::Rotary ? 180.0 / kPi : 1.0;
            s.axes[i].position = t.actual[static_cast<int>(i)] * k;
            s.axes[i].following_error = t.error[static_cast<int>(i)] * k;
        }
    }
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

void attachShopfloor(CutCell::ui::MainWindow& window) {
    Shopfloor& s = station();
    s.window = &window;
    auto* panel = new CutCell::ui::JobQueuePanel(stationJobQueue(), window.document(), &window);
    window.addBottomTab(panel, CutCell::ui::JobQueuePanel::tr("Job queue"));
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
        st.link->submit(snapshotOf(window)); // returns at once (the node diffs and queues)
        const QString text = CutCell::ui::JobQueuePanel::tr("Shop floor: %1")
                                 .arg(QString::fromStdString(st.link->status().text));
        linkLabel->setText(text);
        panel->setLinkText(text);
    });
    timer->start();
}

} // namespace cutcell::app
