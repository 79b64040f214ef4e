#pragma once
// The parameter forms grouped as an engineer thinks: the common pages (Job, and Pipes and Cut
// for the machines that cut a pipe joint), the pages
// of the job's machine (MachineUi::formPages, e.g. Method, Robot, Controller for the robot),
// then Cycle & devices; each in a scrollable tab whose title counts its invalid fields. Every
// registered machine's pages are built once and shown while the job is for that machine.
// Issues no form shows (e.g. an unknown machine) are listed under the tabs.
//
// Threading contract: GUI thread only.
#include "ui/forms/job_editor.h"

#include <QWidget>

#include <vector>

class QLabel;
class QTabWidget;

namespace CutCell::ui {

class JobForm;
class MachineUi;

class ParameterTabs : public QWidget {
    Q_OBJECT
  public:
    explicit ParameterTabs(JobEditor* editor, QWidget* parent = nullptr);

    // The field showing the key: on the job machine's own pages before the common ones.
    QWidget* fieldFor(const std::string& key) const;
    // An issue as the operator reads it: named by its field's label when a form shows the key,
    // a range issue in the GUI's language (issueText).
    QString issueMessage(const cutcell::JobIssue& issue) const;
    // A sentence from core (a planner's refusal) with every job key a form shows
    // ("machine.carriage.max_speed_mm_s") replaced by that field's label.
    QString withFieldLabels(QString text) const;
    // Shows the tab holding the field and focuses it.
    void revealField(const std::string& key);
    QTabWidget* tabs() const { return tabs_; }
    void setEditingLocked(bool locked, const QString& reason);
    // Read-only, with the level they need, every field the editor's gate refuses (user
    // levels); again after each new job and whenever the user changes.
    void applyAccess();
    // Whether the tab with this (untranslated-count) title is shown for the current machine.
    bool tabShown(const QString& title) const;
    // Shows the n-th visible tab (the tab list depends on the machine).
    void showVisibleTab(int n);

  private:
    void refreshTitles();
    // Shows the pages of the job's machine, hides the others; disables the common fields the
    // machine does not use.
    void applyMachine();
    bool formActive(size_t i) const; // a common page or a page of the job's machine
    // The form whose field shows `key`: the job machine's own page before a common one; -1.
    int formShowing(const std::string& key) const;

    JobEditor* editor_;
    QTabWidget* tabs_;
    QLabel* otherIssues_;
    QLabel* lockNote_;
    std::vector<JobForm*> forms_;
    std::vector<const MachineUi*> owners_; // null: common page
    const MachineUi* machine_ = nullptr;
    bool machineApplied_ = false;
    std::vector<QWidget*> disabledFields_;
    QStringList titles_;
};

} // namespace CutCell::ui
