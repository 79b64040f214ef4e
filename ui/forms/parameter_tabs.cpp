#include "ui/forms/parameter_tabs.h"

#include "ui/forms/cut_form.h"
#include "ui/forms/cycle_devices_form.h"
#include "ui/forms/issue_text.h"
#include "ui/forms/job_info_form.h"
#include "ui/forms/narrow_page.h"
#include "ui/forms/pipes_form.h"
#include "ui/machine/machine_ui_registry.h"

#include <QIcon>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QRegularExpression>
#include <QScrollArea>
#include <QTabBar>
#include <QTabWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <set>

namespace CutCell::ui {
namespace {

// A red dot for tabs holding invalid fields (icons are not overridden by the stylesheet).
QIcon issueIcon() {
    QPixmap pm(12, 12);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    p.setBrush(QColor(255, 74, 61));
    p.setPen(Qt::NoPen);
    p.drawEllipse(1, 1, 10, 10);
    return QIcon(pm);
}

} // namespace

ParameterTabs::ParameterTabs(JobEditor* editor, QWidget* parent)
    : QWidget(parent), editor_(editor), tabs_(new QTabWidget(this)), otherIssues_(new QLabel(this)),
      lockNote_(new QLabel(this)) {
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    lockNote_->setObjectName("lockNote");
    lockNote_->setWordWrap(true);
    lockNote_->hide();
    tabs_->setObjectName("parameterTabs");
    tabs_->setUsesScrollButtons(true);
    // The issue icon no taller than the titles' text: at the default 16 px it made the tab bar
    // 2 px taller as the first bad value came, and every field moved down with it.
    tabs_->setIconSize(QSize(12, 12));
    v->addWidget(tabs_, 1);
    // The notes go below the forms: one shown above them pushed every field down ~30 px as it
    // came (at Start, at a typing error), and the click meant for a field landed in the next.
    v->addWidget(lockNote_);
    otherIssues_->setObjectName("formIssues");
    otherIssues_->setWordWrap(true);
    otherIssues_->hide();
    v->addWidget(otherIssues_);

    const auto add = [this](JobForm* form, const QString& title, const MachineUi* owner) {
        auto* scroll = new QScrollArea(tabs_);
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidget(form);
        narrowPage(form);
        tabs_->addTab(scroll, title);
        forms_.push_back(form);
        owners_.push_back(owner);
        titles_ << title;
    };
    // Common pages first, then every machine's own pages (shown while the job is for that
    // machine), then the cycle and devices.
    // The Pipes and Cut pages describe a pipe joint: a machine that uses none of their fields
    // (unusedCommonFields) does not show them (applyMachine).
    add(new JobInfoForm(editor), tr("Job"), nullptr);
    add(new PipesForm(editor), tr("Pipes"), nullptr);
    add(new CutForm(editor), tr("Cut"), nullptr);
    for (const MachineUi* machine : machineUis())
        for (const FormPage& page : machine->formPages())
            add(page.make(editor), page.title, machine);
    add(new CycleDevicesForm(editor), tr("Cycle && devices"), nullptr);
    connect(editor, &JobEditor::jobReset, this, &ParameterTabs::applyMachine);
    connect(editor, &JobEditor::edited, this, &ParameterTabs::applyMachine);
    connect(editor, &JobEditor::jobReset, this, &ParameterTabs::applyAccess);
    applyMachine();
    // After the forms: they mark their fields first, the titles count them.
    connect(editor, &JobEditor::issuesChanged, this, &ParameterTabs::refreshTitles);
    refreshTitles();
}

bool ParameterTabs::formActive(size_t i) const {
    return owners_[i] == nullptr || owners_[i] == machine_;
}

int ParameterTabs::formShowing(const std::string& key) const {
    // The machine's own pages first: a key one of them shows too (the section steel's cut chart
    // on its Section page) is that page's; the common page's field is hidden or greyed with
    // the machine's unusedCommonFields.
    for (const bool own : {true, false})
        for (size_t i = 0; i < forms_.size(); ++i)
            if (formActive(i) && (owners_[i] != nullptr) == own && forms_[i]->fieldFor(key))
                return static_cast<int>(i);
    return -1;
}

QWidget* ParameterTabs::fieldFor(const std::string& key) const {
    const int i = formShowing(key);
    return i < 0 ? nullptr : forms_[static_cast<size_t>(i)]->fieldFor(key);
}

void ParameterTabs::showVisibleTab(int n) {
    for (int i = 0; i < tabs_->count(); ++i)
        if (tabs_->isTabVisible(i) && n-- == 0) {
            tabs_->setCurrentIndex(i);
            return;
        }
}

void ParameterTabs::revealField(const std::string& key) {
    const int i = formShowing(key);
    if (i < 0) return;
    tabs_->setCurrentIndex(i);
    forms_[static_cast<size_t>(i)]->fieldFor(key)->setFocus(Qt::OtherFocusReason);
}

bool ParameterTabs::tabShown(const QString& title) const {
    for (int i = 0; i < static_cast<int>(titles_.size()); ++i)
        if (titles_[i] == title && tabs_->isTabVisible(i)) return true;
    return false;
}

void ParameterTabs::applyMachine() {
    const MachineUi* machine = machineUiFor(editor_->job());
    if (machine == machine_ && machineApplied_) return;
    machine_ = machine;
    machineApplied_ = true;
    // Only this machine's pages; an unknown machine (its issue is listed under the tabs) keeps
    // the common pages only.
    for (size_t i = 0; i < forms_.size(); ++i)
        tabs_->setTabVisible(static_cast<int>(i), formActive(i));
    for (auto* field : disabledFields_) {
        field->setEnabled(true);
        field->setToolTip(QString());
    }
    disabledFields_.clear();
    if (!machine) return;
    std::set<std::string> unused;
    std::vector<std::pair<std::string, QString>> unusedFields = machine->unusedCommonFields();
    // The engine's limits of an axis kind the machine does not have.
    bool rotary = false, linear = false;
    for (const AxisLabel& a : machine->axes())
        (a.linear() ? linear : rotary) = true;
    if (!linear)
        for (const char* key : {"engine.following_error_limit_mm", "engine.home_speed_mm_s"})
            unusedFields.push_back({key, tr("This machine has no linear axis.")});
    if (!rotary)
        for (const char* key : {"engine.following_error_limit_deg", "engine.home_speed_deg_s"})
            unusedFields.push_back({key, tr("This machine has no rotary axis.")});
    // Only the common pages' fields: the machine's own pages may show the same key (its cut
    // chart) and use it.
    for (const auto& [key, reason] : unusedFields) {
        unused.insert(key);
        for (size_t i = 0; i < forms_.size(); ++i)
            if (owners_[i] == nullptr)
                if (auto* field = forms_[i]->fieldFor(key)) {
                    field->setEnabled(false);
                    field->setToolTip(reason);
                    disabledFields_.push_back(field);
                }
    }
    // A common page none of whose fields this machine uses is not shown at all (the Pipes and
    // Cut pages of the machines that do not cut a pipe joint); a page with some used fields
    // stays, its unused fields greyed with the reason.
    for (size_t i = 0; i < forms_.size(); ++i) {
        if (owners_[i] != nullptr) continue;
        const std::vector<std::string> keys = forms_[i]->keys();
        const bool allUnused =
            !keys.empty() && std::all_of(keys.begin(), keys.end(),
                                         [&](const auto& k) { return unused.count(k) > 0; });
        if (allUnused) tabs_->setTabVisible(static_cast<int>(i), false);
    }
}

void ParameterTabs::setEditingLocked(bool locked, const QString& reason) {
    for (auto* f : forms_)
        f->setEditingLocked(locked);
    lockNote_->setVisible(locked);
    lockNote_->setText(reason);
}

void ParameterTabs::applyAccess() {
    for (auto* f : forms_)
        f->applyAccess();
}

QString ParameterTabs::issueMessage(const cutcell::JobIssue& issue) const {
    const QWidget* field = fieldFor(issue.key);
    return issueText(issue, field ? field->accessibleName() : QString());
}

QString ParameterTabs::withFieldLabels(QString text) const {
    // A key: dotted lower-case names, indices allowed ("other_branches[1].angle_deg"); in the
    // file a machine's keys stand under "machine.", the forms know them without it.
    static const QRegularExpression keyPattern(QStringLiteral(
        R"((?<![\w.])(?:machine\.)?([a-z][a-z0-9_]*(?:\[\d+\])?(?:\.[a-z][a-z0-9_]*(?:\[\d+\])?)+))"));
    QString out;
    qsizetype done = 0;
    for (auto it = keyPattern.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        const QWidget* field = fieldFor(m.captured(1).toStdString());
        if (!field || field->accessibleName().isEmpty()) continue;
        out += text.mid(done, m.capturedStart() - done) + field->accessibleName();
        done = m.capturedEnd();
    }
    return out + text.mid(done);
}

void ParameterTabs::refreshTitles() {
    QStringList other;
    for (const auto& issue : editor_->issues())
        if (!fieldFor(issue.key)) other << issueMessage(issue);
    otherIssues_->setVisible(!other.isEmpty());
    otherIssues_->setText(other.join('\n'));
    for (size_t i = 0; i < forms_.size(); ++i) {
        const int n = formActive(i) ? forms_[i]->markedCount() : 0;
        const int idx = static_cast<int>(i);
        tabs_->setTabText(idx,
                          n ? QStringLiteral("%1 (%2)").arg(titles_[idx]).arg(n) : titles_[idx]);
        tabs_->setTabIcon(idx, n ? issueIcon() : QIcon());
    }
}

} // namespace CutCell::ui
