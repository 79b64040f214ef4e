#include "ui/forms/job_editor.h"

#include "core/machine/pipe_joint_section.h"

namespace CutCell::ui {

JobEditor::JobEditor(QObject* parent) : QObject(parent) {
    revalidate();
}

std::vector<cutcell::JobIssue> JobEditor::issuesFor(const std::string& key) const {
    std::vector<cutcell::JobIssue> out;
    for (const auto& i : issues_)
        if (i.key == key) out.push_back(i);
    return out;
}

void JobEditor::setJob(const cutcell::Job& job) {
    job_ = job;
    revalidate();
    emit jobReset();
    emit issuesChanged();
}

void JobEditor::edit(const std::function<void(cutcell::Job&)>& change) {
    change(job_);
    // The cut chart's speed follows the pipes, the target and the process.
    cutcell::syncProcessSpeed(job_);
    revalidate();
    emit edited();
    emit issuesChanged();
}

bool JobEditor::editKey(const std::string& key, const QString& oldValue, const QString& newValue,
                        const std::function<void(cutcell::Job&)>& change) {
    if (const QString why = lockReason(key); !why.isEmpty()) {
        emit editRefused(QString::fromStdString(key), why);
        return false;
    }
    edit(change);
    if (oldValue != newValue)
        emit parameterChanged(QString::fromStdString(key), oldValue, newValue);
    return true;
}

void JobEditor::cutChartsChanged() {
    cutcell::Job synced = job_;
    cutcell::syncProcessSpeed(synced);
    if (synced.cut.speed_mm_s != job_.cut.speed_mm_s) {
        edit([](cutcell::Job&) {}); // edit() takes the new chart's speed
        return;
    }
    revalidate();
    emit issuesChanged();
}

void JobEditor::revalidate() {
    issues_ = cutcell::validateJob(job_);
}

} // namespace CutCell::ui
