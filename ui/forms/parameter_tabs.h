#pragma once
// The parameter forms grouped as an engineer thinks (Pipes, Cut, Method, Robot, Controller,
// Cycle & devices), each in a scrollable tab whose title counts its invalid fields. Issues no
// form shows (e.g. an unknown machine) are listed under the tabs.
//
// Threading contract: GUI thread only.
#include "ui/forms/job_editor.h"

#include <QWidget>

#include <vector>

class QLabel;
class QTabWidget;

namespace CutCell::ui {

class JobForm;

class ParameterTabs : public QWidget {
    Q_OBJECT
  public:
    explicit ParameterTabs(JobEditor* editor, QWidget* parent = nullptr);

    QWidget* fieldFor(const std::string& key) const;
    // Shows the tab holding the field and focuses it.
    void revealField(const std::string& key);
    QTabWidget* tabs() const { return tabs_; }
    void setEditingLocked(bool locked, const QString& reason);
    // Whether the tab with this (untranslated-count) title is shown for the current machine.
    bool tabShown(const QString& title) const;

  private:
    void refreshTitles();
    // Shows the pages of the job's machine (robot or profile cutter), hides the others.
    void applyMachine();

    JobEditor* editor_;
    QTabWidget* tabs_;
    QLabel* otherIssues_;
    QLabel* lockNote_;
    std::vector<JobForm*> forms_;
    QStringList titles_;
};

} // namespace CutCell::ui
