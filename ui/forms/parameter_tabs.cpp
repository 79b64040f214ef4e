#include "ui/forms/parameter_tabs.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"

#include "ui/forms/controller_form.h"
#include "ui/forms/cut_form.h"
#include "ui/forms/cycle_devices_form.h"
#include "ui/forms/method_form.h"
#include "ui/forms/pipes_form.h"
#include "ui/forms/profile_cutter_form.h"
#include "ui/forms/robot_dh_table_form.h"

#include <QIcon>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QScrollArea>
#include <QTabBar>
#include <QTabWidget>
#include <QVBoxLayout>

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
    v->addWidget(lockNote_);
    tabs_->setObjectName("parameterTabs");
    tabs_->setUsesScrollButtons(true);
    v->addWidget(tabs_, 1);
    otherIssues_->setObjectName("formIssues");
    otherIssues_->setWordWrap(true);
    otherIssues_->hide();
    v->addWidget(otherIssues_);

    const auto add = [this](JobForm* form, const QString& title) {
        auto* scroll = new QScrollArea(tabs_);
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidget(form);
        tabs_->addTab(scroll, title);
        forms_.push_back(form);
        titles_ << title;
    };
    add(new PipesForm(editor), tr("Pipes"));
    add(new CutForm(editor), tr("Cut"));
    add(new MethodForm(editor), tr("Method"));
    add(new RobotDhTableForm(editor), tr("Robot"));
    add(new ControllerForm(editor), tr("Controller"));
    add(new CycleDevicesForm(editor), tr("Cycle && devices"));
    add(new ProfileCutterForm(editor), tr("Profile cutter"));
    connect(editor, &JobEditor::jobReset, this, &ParameterTabs::applyMachine);
    connect(editor, &JobEditor::edited, this, &ParameterTabs::applyMachine);
    applyMachine();
    // After the forms: they mark their fields first, the titles count them.
    connect(editor, &JobEditor::issuesChanged, this, &ParameterTabs::refreshTitles);
    refreshTitles();
}

QWidget* ParameterTabs::fieldFor(const std::string& key) const {
    for (auto* f : forms_)
        if (auto* w = f->fieldFor(key)) return w;
    return nullptr;
}

void ParameterTabs::revealField(const std::string& key) {
    for (size_t i = 0; i < forms_.size(); ++i)
        if (auto* w = forms_[i]->fieldFor(key)) {
            tabs_->setCurrentIndex(static_cast<int>(i));
            w->setFocus(Qt::OtherFocusReason);
            return;
        }
}

bool ParameterTabs::tabShown(const QString& title) const {
    const int i = static_cast<int>(titles_.indexOf(title));
    return i >= 0 && tabs_->isTabVisible(i);
}

void ParameterTabs::applyMachine() {
    // Robot-only pages (how the robot cuts, its DH table) give way to the profile cutter's.
    const bool profile = editor_->job().machine == cutcell::kProfileCutterId;
    const auto show = [this](const QString& title, bool on) {
        const int i = static_cast<int>(titles_.indexOf(title));
        if (i >= 0) tabs_->setTabVisible(i, on);
    };
    show(tr("Method"), !profile);
    show(tr("Robot"), !profile);
    show(tr("Profile cutter"), profile);
    if (auto* bevel = fieldFor("cut.bevel_deg")) {
        bevel->setEnabled(!profile);
        bevel->setToolTip(profile ? tr("The profile cutter's torch stands radial: no bevel.")
                                  : QString());
    }
    if (auto* tilt = fieldFor("cut.max_direction_deviation_deg")) tilt->setEnabled(!profile);
}

void ParameterTabs::setEditingLocked(bool locked, const QString& reason) {
    for (auto* f : forms_)
        f->setEnabled(!locked);
    lockNote_->setVisible(locked);
    lockNote_->setText(reason);
}

void ParameterTabs::refreshTitles() {
    QStringList other;
    for (const auto& issue : editor_->issues())
        if (!fieldFor(issue.key)) other << QString::fromStdString(issue.message);
    otherIssues_->setVisible(!other.isEmpty());
    otherIssues_->setText(other.join('\n'));
    for (size_t i = 0; i < forms_.size(); ++i) {
        const int n = forms_[i]->markedCount();
        const int idx = static_cast<int>(i);
        tabs_->setTabText(idx,
                          n ? QStringLiteral("%1 (%2)").arg(titles_[idx]).arg(n) : titles_[idx]);
        tabs_->setTabIcon(idx, n ? issueIcon() : QIcon());
    }
}

} // namespace CutCell::ui
