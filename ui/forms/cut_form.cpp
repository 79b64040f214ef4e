#include "ui/forms/cut_form.h"

#include "core/machine/pipe_joint_section.h"
#include "ui/forms/process_form.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::CutTarget;
using cutcell::Job;

CutForm::CutForm(JobEditor* editor, QWidget* parent) : JobForm(editor, parent) {
    auto* what = new QGroupBox(tr("Target and bevel"), this);
    auto* f = new QFormLayout(what);
    addRow(f, tr("Cut"),
           bindChoice(
               "cut.target", {tr("Hole in the main pipe"), tr("End of the branch pipe")},
               [](const Job& j) { return j.cut.target == CutTarget::Main ? 0 : 1; },
               [](Job& j, int i) { j.cut.target = i == 0 ? CutTarget::Main : CutTarget::Branch; }),
           {});
    addRow(f, tr("Bevel angle"),
           bindDouble("cut.bevel_deg", 2, [](Job& j) -> double& { return j.cut.bevel_deg; }),
           "deg");
    mainLayout()->addWidget(what);

    auto* speed = new QGroupBox(tr("Speed"), this);
    auto* s = new QFormLayout(speed);
    auto* cutSpeed =
        bindDouble("cut.speed_mm_s", 3, [](Job& j) -> double& { return j.cut.speed_mm_s; });
    addRow(s, tr("Cutting speed"), cutSpeed, "mm/s");
    // With a cut chart the speed is the chart's (or its override).
    const auto showSpeedSource = [cutSpeed, editor] {
        const bool chart = editor->job().process.used;
        const QSignalBlocker block(cutSpeed);
        cutSpeed->setValue(editor->job().cut.speed_mm_s);
        cutSpeed->setReadOnly(chart);
        cutSpeed->setToolTip(chart ? tr("From the cut chart (above on this page); set an override "
                                        "there to cut at another speed.")
                                   : QString());
    };
    connect(editor, &JobEditor::jobReset, cutSpeed, showSpeedSource);
    connect(editor, &JobEditor::edited, cutSpeed, showSpeedSource);
    addRow(s, tr("Start / stop ramp"),
           bindDouble("cut.ramp_s", 3, [](Job& j) -> double& { return j.cut.ramp_s; }), "s");
    mainLayout()->addWidget(speed);

    auto* path = new QGroupBox(tr("Path"), this);
    auto* p = new QFormLayout(path);
    addRow(p, tr("Knot spacing"),
           bindDouble("cut.knot_spacing_mm", 3,
                      [](Job& j) -> double& { return j.cut.knot_spacing_mm; }),
           "mm");
    addRow(p, tr("Max. torch tilt"),
           bindDouble("cut.max_direction_deviation_deg", 2,
                      [](Job& j) -> double& { return j.cut.max_direction_deviation_deg; }),
           "deg");
    auto* autoPhi = bindBool("cut.start_phi_auto", tr("automatic start point"),
                             [](Job& j) -> bool& { return j.cut.start_phi_auto; });
    p->addRow(tr("Start point"), autoPhi);
    auto* phi =
        bindDouble("cut.start_phi_deg", 2, [](Job& j) -> double& { return j.cut.start_phi_deg; });
    addRow(p, tr("Start angle phi"), phi, "deg");
    connect(autoPhi, &QCheckBox::toggled, phi, [phi](bool on) { phi->setEnabled(!on); });
    connect(editor, &JobEditor::jobReset, phi,
            [phi, editor] { phi->setEnabled(!editor->job().cut.start_phi_auto); });
    mainLayout()->addWidget(path);
    // The cut chart (issue 24) first on this page, not a tab of its own: at 1280x720 one more
    // tab pushed "Cycle & devices" off the tab bar.
    // The part's wall: the cut pipe's (the main pipe's for a hole, the branch's for its end).
    ProcessPart part;
    part.wallMm = [](const Job& j) { return cutcell::cutPartWallMm(j); };
    addSubForm(new ProcessForm(editor, std::move(part), this), 0);
    mainLayout()->addStretch(1);
}

} // namespace CutCell::ui
