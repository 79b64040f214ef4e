#pragma once
// The job being edited: one Job value, its validation issues and an edit counter. Forms read
// it on jobReset() and write through edit(); every edit re-validates with core validateJob().
//
// Threading contract: GUI thread only.
#include "core/job/job.h"
#include "core/job/job_io.h"

#include <QObject>
#include <QString>

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
    // One change of the field `key` from a form, if the gate lets it through (user levels):
    // then as edit(), and parameterChanged(key, old, new) for the audit trail; else nothing
    // changes, editRefused(key, why) is emitted and false returned (the form shows the old
    // value again).
    bool editKey(const std::string& key, const QString& oldValue, const QString& newValue,
                 const std::function<void(cutcell::Job&)>& change);
    // The gate: "" lets a key be changed, else the reason it may not ("needs the engineer
    // level"). None by default (every key may be changed).
    using Gate = std::function<QString(const std::string& key)>;
    void setGate(Gate gate) { gate_ = std::move(gate); }
    // The gate for a whole job from a file (JobDocument::open): "" lets it replace this one,
    // else why not (it changes a machine parameter above the user's level).
    using OpenGate = std::function<QString(const cutcell::Job& from, const cutcell::Job& to)>;
    void setOpenGate(OpenGate gate) { openGate_ = std::move(gate); }
    QString openLockReason(const cutcell::Job& to) const {
        return openGate_ ? openGate_(job_, to) : QString();
    }
    // The active cut-chart library was replaced (the cut-chart editor saved the user's table):
    // the cut speed follows the new chart (an edit, when it changes it) and the job is checked
    // again against the new charts (issuesChanged).
    void cutChartsChanged();
    // Why `key` may not be changed now ("" when it may).
    QString lockReason(const std::string& key) const { return gate_ ? gate_(key) : QString(); }

  signals:
    void jobReset();
    void edited();
    void issuesChanged();
    void parameterChanged(const QString& key, const QString& oldValue, const QString& newValue);
    void editRefused(const QString& key, const QString& why);

  private:
    void revalidate();

    cutcell::Job job_;
    std::vector<cutcell::JobIssue> issues_;
    Gate gate_;
    OpenGate openGate_;
};

} // namespace CutCell::ui
