#include "ui/forms/job_editor.h"

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
    revalidate();
    emit edited();
    emit issuesChanged();
}

void JobEditor::revalidate() {
    issues_ = cutcell::validateJob(job_);
}

} // namespace CutCell::ui
