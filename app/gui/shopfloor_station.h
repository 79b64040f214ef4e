#pragma once
// The operator station on the shop floor (issue 26): the Sparkplug B edge node
// (devices/shopfloor/) run with the station when a configuration file is given (`--shopfloor
// FILE`, or $XDG_CONFIG_HOME/cutcell/shopfloor.json when it exists; `--shopfloor off`). The
// window's state goes out ten times a second (the node publishes what changed); the network's
// commands come in on the link's thread: a job is validated there (the refusal is the answer)
// and queued on the GUI thread for the operator to open and start; a feed hold acts at once;
// Start, Reset and an E-STOP release never come from the network (the node refuses them).
// The Job queue tab's "Link settings…" edits the file the station uses (shopfloor_settings.h;
// the engineer level where user levels exist) and restarts the link with it.
#include "core/shopfloor/cell_snapshot.h"
#include "core/shopfloor/shopfloor_command_sink.h"

#include <QObject>

#include <string>

namespace CutCell::ui {
class MainWindow;
class JobQueue;
} // namespace CutCell::ui

namespace cutcell::app {

// Opens the link ("" = the default file if it exists, "off" = none); a line for the operator.
std::string openShopfloor(const std::string& configPath);
// A clean NDEATH and the link closed (the program's end).
void closeShopfloor();
// The file "Link settings…" edits: the one openShopfloor was given, else the default file (also
// with "off": the link then stays off until the next start).
std::string shopfloorSettingsPath();
// The window's Job queue tab, its status-bar state and snapshots (each window, also a rebuilt
// one: the queue and the link carry over).
void attachShopfloor(CutCell::ui::MainWindow& window);
// The window's state now as the shop floor sees it: machine, job, state, progress, axes, what
// was made, the active alarms, the last run's figures, consumables, the queue's length.
shopfloor::CellSnapshot stationSnapshot(CutCell::ui::MainWindow& window);
// The queue every window shows (always there: jobs may come from other sources too).
CutCell::ui::JobQueue* stationJobQueue();

// The commands of the network (the link's thread): public for the tests.
class StationCommands final : public shopfloor::ShopfloorCommandSink {
  public:
    std::string queueJob(const std::string& jobText, const std::string& source) override;
    void feedHold() override;
    void clearQueue() override;
};

} // namespace cutcell::app
