#include "ui/job_queue.h"

namespace CutCell::ui {

void JobQueue::add(const cutcell::Job& job, const QString& source) {
    entries_.push_back({job, source, QDateTime::currentDateTime()});
    emit changed();
}

bool JobQueue::take(int row, Entry* out) {
    if (row < 0 || row >= size()) return false;
    if (out) *out = entries_[static_cast<size_t>(row)];
    entries_.erase(entries_.begin() + row);
    emit changed();
    return true;
}

void JobQueue::remove(int row) {
    take(row, nullptr);
}

void JobQueue::clear() {
    if (entries_.empty()) return;
    entries_.clear();
    emit changed();
}

} // namespace CutCell::ui
