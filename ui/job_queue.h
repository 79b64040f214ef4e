#pragma once
// Jobs waiting at the station (issue 26): sent by the shop floor (an MES's NCMD through the
// Sparkplug link) or any other source, each validated like a file opened by hand before it gets
// here. Nothing starts a queued job: the operator opens it (it becomes the job being edited)
// and presses Start as for any job.
//
// Threading contract: GUI thread only (the link's thread posts to it).
#include "core/job/job.h"

#include <QDateTime>
#include <QObject>
#include <QString>

#include <vector>

namespace CutCell::ui {

class JobQueue : public QObject {
    Q_OBJECT
  public:
    struct Entry {
        cutcell::Job job;
        QString source; // "shop floor: spBv1.0/shop/NCMD/cell-1"
        QDateTime received;
    };

    explicit JobQueue(QObject* parent = nullptr) : QObject(parent) {}

    const std::vector<Entry>& entries() const { return entries_; }
    int size() const { return static_cast<int>(entries_.size()); }
    void add(const cutcell::Job& job, const QString& source);
    // The entry (removed from the queue); false when there is none at `row`.
    bool take(int row, Entry* out);
    void remove(int row);
    void clear();

  signals:
    void changed();

  private:
    std::vector<Entry> entries_;
};

} // namespace CutCell::ui
