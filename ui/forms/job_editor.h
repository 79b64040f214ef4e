#pragma once
// The job being edited: one Job value, its validation issues and an edit counter. Forms read
// it on jobReset() and write through edit(); every edit re-validates with core validateJob().
//
// Threading contract: GUI thread only.
#include "core/job/job.h"
#include "core/job/job_io.h"

#include <QObject>

#include <functional>
#include <vector>

namespace CutCell::ui {

class JobEditor : public QObject {
    Q_OBJECT
  public:
    explicit JobEditor(QObject* parent = nullptr);

    const cutcell::Job& job() const { return job_; }
    const std::vector<cutcell::JobIssue>& issues() const { return issues_; }
    bool valid() const { return issues_.empty(); }
    // Issues whose key is exactly `key` (a form field).
    std::vector<cutcell::JobIssue> issuesFor(const std::string& key) const;

    // Replaces the whole job (open, new): forms reload, no edit is recorded.
    void setJob(const cutcell::Job& job);
    // Applies one change from a form; emits edited() and issuesChanged().
    void edit(const std::function<void(cutcell::Job&)>& change);

  signals:
    void jobReset();
    void edited();
    void issuesChanged();

  private:
    void revalidate();

    cutcell::Job job_;
    std::vector<cutcell::JobIssue> issues_;
};

} // namespace CutCell::ui
