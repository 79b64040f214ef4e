#include "ui/machines/pipe_robot/method_form.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "ui/forms/edited_spec.h"
#ifdef CUTCELL_HAVE_PLOTS
#include "ui/machines/pipe_robot/method_comparison_page.h"
#endif

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::CutMethod;
using cutcell::Job;

namespace {

QString explain(CutMethod m) {
    return m == CutMethod::StaticPipe
               ? QObject::tr("Static pipe: the chuck holds the pipe at a fixed angle and the "
                             "arm follows the whole saddle curve around it.")
               : QObject::tr("Rotating pipe: the chuck turns the pipe so that the cut point "
                             "stays on top; the torch moves on a short straight line.");
}

} // namespace

MethodForm::MethodForm(JobEditor* editor, QWidget* parent) : JobForm(editor, parent) {
    auto* box = new QGroupBox(tr("Cutting method"), this);
    auto* f = new QFormLayout(box);
    auto* method = bindChoice(
        "method", {tr("Rotating pipe"), tr("Static pipe")},
        [](const Job& j) {
            return editedSpec<cutcell::PipeRobotSpec>(j).method == CutMethod::RotatingPipe ? 0 : 1;
        },
        [](Job& j, int i) {
            editedSpec<cutcell::PipeRobotSpec>(j).method =
                i == 0 ? CutMethod::RotatingPipe : CutMethod::StaticPipe;
        });
    addRow(f, tr("Method"), method, {});
    auto* text = new QLabel(box);
    text->setWordWrap(true);
    text->setObjectName("hint");
    f->addRow(text);
    auto* chuck = bindDouble("cut.static_chuck_deg", 2,
                             [](Job& j) -> double& { return j.cut.static_chuck_deg; });
    addRow(f, tr("Chuck angle (static)"), chuck, "deg");
    const auto refresh = [text, chuck, editor] {
        text->setText(explain(editedSpec<cutcell::PipeRobotSpec>(editor->job()).method));
        chuck->setEnabled(editedSpec<cutcell::PipeRobotSpec>(editor->job()).method ==
                          CutMethod::StaticPipe);
    };
    connect(editor, &JobEditor::jobReset, this, refresh);
    connect(editor, &JobEditor::edited, this, refresh);
    refresh();
    mainLayout()->addWidget(box);
#ifdef CUTCELL_HAVE_PLOTS
    // Both methods side by side (seed 000, Fig. 11-14) where the method is chosen: a tab of
    // its own pushed "Cycle & devices" off the tab bar at 1280x720.
    mainLayout()->addWidget(new MethodComparisonForm(editor, this));
#endif
    mainLayout()->addStretch(1);
}

} // namespace CutCell::ui
