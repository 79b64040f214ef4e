#pragma once
// The fieldbus in the operator column (hidden for in-process drives): the bus state - down,
// connecting with the nodes configured so far, up, lost, failed with the reason - one row per
// node (node, NMT state, CiA 402 state, heartbeat age; the axis in the tooltip), a row greyed
// when its last heartbeat is older than the heartbeat timeout, and Reconnect. A bus that is up
// while nodes have gone silent (a drive powered off, its cable pulled) does not say "up ... N
// nodes operational": the state names how many nodes are silent and which, in red.
//
// Fed with plain data: the link (RunController::linkChanged) and the device snapshot (the main
// window's device timer). Threading contract: GUI thread only; it only emits requests.
#include "ui/device_panel.h"
#include "ui/engine_rig.h"

#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace CutCell::ui {

class BusPanel : public QWidget {
    Q_OBJECT
  public:
    explicit BusPanel(QWidget* parent = nullptr);

    void setLink(const RigLink& link);
    void setSnapshot(const cutcell::ui::DevicePanelSnapshot& snapshot);

    QLabel* stateLabel() const { return state_; }
    QLabel* detailLabel() const { return detail_; }
    QPushButton* reconnectButton() const { return reconnect_; }
    QTableWidget* nodeTable() const { return nodes_; }
    // Whether a node's row is shown stale (greyed): no heartbeat within the timeout.
    bool rowStale(int row) const;

  signals:
    void reconnectRequested();

  private:
    void refreshRows();
    void refreshState();

    QLabel* state_;
    QLabel* detail_;
    QProgressBar* progress_;
    QTableWidget* nodes_;
    QPushButton* reconnect_;
    RigLink link_;
    cutcell::ui::DevicePanelSnapshot snapshot_;
    std::vector<bool> stale_;
};

} // namespace CutCell::ui
