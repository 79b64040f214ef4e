#pragma once
// The alarm list, apart from the event log: every emergency stop and fault with its time,
// source (axis, node, the machine's tool, operator), text and what to do about it. An alarm is
// active until the engine is reset out of the latched state, then it stays in the list as past; the
// operator acknowledges alarms (Acknowledge), which the list shows. The alarms of a run are written
// as alarms.json into that run's log folder (atomically, again after each acknowledgement), and
// File -> Export alarms writes the whole list as CSV.
//
// Threading contract: GUI thread only.
#include "core/engine/engine_types.h"
#include "core/engine/run_terms.h"

#include <QDateTime>
#include <QString>
#include <QWidget>

#include <map>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace CutCell::ui {

struct Alarm {
    QDateTime time;
    QString source; // "axis 2 (q2 shoulder)", "node 3", "torch", "operator", "engine"
    QString text;   // in the GUI's language
    QString logged; // as core wrote it (English, C notation): what the files keep
    QString action; // what to do
    std::uint32_t run_id = 0;
    bool active = true;
    bool acknowledged = false;
};

class AlarmPanel : public QWidget {
    Q_OBJECT
  public:
    static constexpr const char* kAcknowledgeKey = "F12"; // from anywhere in the window
    explicit AlarmPanel(QWidget* parent = nullptr);

    // Raises an alarm for a fault or an emergency stop event; other events are ignored.
    void addEngineEvent(const cutcell::EngineEvent& e);
    void raise(const Alarm& alarm);
    // The engine's state: leaving EmergencyStop/Fault (Reset) makes the active alarms past.
    void setState(cutcell::EngineState state);
    void acknowledgeAll();
    // Where the run's log lives: alarms.json is written there now and after each change.
    void setRunDirectory(std::uint32_t runId, const QString& dir);

    const std::vector<Alarm>& alarms() const { return alarms_; }
    int activeCount() const;
    int unacknowledgedCount() const;
    QTableWidget* table() const { return table_; }
    QPushButton* acknowledgeButton() const { return ack_; }

    bool exportCsv(const QString& path, QString* error = nullptr) const;
    // The alarms of one run as JSON (an array of objects).
    QByteArray runJson(std::uint32_t runId) const;

    // Source and what-to-do for an engine fault text (e.g. "axis 2 (q2 shoulder): following
    // error ...").
    // The tool is the program's (terms.tool: "torch", "saw"); its texts say "<tool>: ...".
    static QString sourceOf(const QString& text, const cutcell::RunTerms& terms = {});
    // The loaded program's terms: the name of its process tool as an alarm source.
    void setTerms(const cutcell::RunTerms& terms) { terms_ = terms; }
    static QString actionFor(const QString& text, bool emergencyStop);

  signals:
    void changed(int active, int unacknowledged);
    void raised(const Alarm& alarm);

  private:
    void refreshRow(int row);
    void refreshSummary();
    void writeRunFiles();

    QLabel* summary_;
    QPushButton* ack_;
    QTableWidget* table_;
    std::vector<Alarm> alarms_;
    std::map<std::uint32_t, QString> runDirs_;
    cutcell::RunTerms terms_;
};

} // namespace CutCell::ui
