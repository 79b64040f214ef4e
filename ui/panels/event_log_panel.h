#pragma once
// The event log: time, severity and message, newest at the bottom, bounded (oldest rows are
// dropped). Faults and emergency stops carry how to clear them.
//
// Threading contract: GUI thread only.
#include "core/engine/engine_types.h"

#include <QDateTime>
#include <QWidget>

class QTableWidget;

namespace CutCell::ui {

class EventLogPanel : public QWidget {
    Q_OBJECT
  public:
    static constexpr int kMaxRows = 2000;
    explicit EventLogPanel(QWidget* parent = nullptr);

    void add(cutcell::Severity severity, const QString& message,
             const QDateTime& when = QDateTime::currentDateTime());
    void addEngineEvent(const cutcell::EngineEvent& e);
    void clear();
    int rowCount() const;
    QString message(int row) const;
    QTableWidget* table() const { return table_; }

    // "What to do" for a state the engine entered (empty when nothing is needed).
    static QString clearHint(cutcell::EngineState to);

  signals:
    void added(cutcell::Severity severity, const QString& message);

  private:
    QTableWidget* table_;
};

} // namespace CutCell::ui
