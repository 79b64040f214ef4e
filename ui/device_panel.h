#pragma once
// The device panel: which drives the job uses (simulated in-process or CANopen with plugin,
// interface, bit rate) and, for CAN, the bus (state, computed load) and every node (NMT state,
// CiA 402 state, heartbeat age, last EMCY, fault), with a fault-reset button.
//
// Fed by a plain snapshot (no device headers here: ui/ knows no transport); app/ converts
// the CAN master's snapshot (app/gui/can_panel_feed.h) and calls setSnapshot() from a GUI
// timer. Threading: GUI thread only; setSnapshot() never waits on anything.
#include <QString>
#include <QWidget>
#include <functional>

#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace cutcell::ui {

struct DevicePanelNode {
    int node = 0;
    QString axis;                 // "0 chuck", "1 arm", ...
    QString nmt;                  // "Operational", ...
    QString cia402;               // "Operation enabled", ...
    double heartbeat_age_ms = -1; // < 0: none yet
    QString last_emcy;            // empty: none
    QString fault;                // master-side fault reason, empty: none
    bool error = false;           // highlight the row
};

struct DevicePanelSnapshot {
    bool can = false;  // false: simulated in-process drives (no bus to show)
    QString bus_state; // "error active", "bus off", "disconnected", ...
    bool bus_error = false;
    double load = 0;                 // fraction of the bit rate (worst-case stuffing)
    QString load_text;               // the figures behind it
    double heartbeat_timeout_ms = 0; // a node row older than this is stale (0: not judged)
    std::vector<DevicePanelNode> nodes;
};

// The device choice as the job's devices section holds it.
struct DeviceChoice {
    bool can = false;
    QString plugin = QStringLiteral("virtualcan");
    QString interface = QStringLiteral("can0");
    int bitrate_bps = 1000000;
};

class DevicePanel : public QWidget {
    Q_OBJECT
  public:
    explicit DevicePanel(QWidget* parent = nullptr);

    void setChoice(const DeviceChoice& c); // from the job (does not emit choiceEdited)
    DeviceChoice choice() const;
    // Hides the choice (kind, plugin, interface, bit rate) where another form edits it.
    void setChoiceVisible(bool visible);
    void setSnapshot(const DevicePanelSnapshot& s);
    // How the master's texts (states, faults, EMCY) are shown: in the GUI's language where the
    // window sets one (CutCell::ui::engineText); as they came by default.
    void setTextTranslator(std::function<QString(const QString&)> shown) {
        shown_ = std::move(shown);
    }

  signals:
    void choiceEdited(const cutcell::ui::DeviceChoice& c); // the operator changed the choice
    void faultResetRequested();

  private:
    void emitChoice();

    QWidget* choiceBox_;
    QComboBox* kind_;
    QLineEdit* plugin_;
    QLineEdit* interface_;
    QSpinBox* bitrate_;
    QLabel* bus_;
    QLabel* load_;
    QTableWidget* nodes_;
    QPushButton* reset_;
    bool updating_ = false;
    std::function<QString(const QString&)> shown_ = [](const QString& s) { return s; };
};

} // namespace cutcell::ui
