#include "ui/forms/pipes_form.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QVBoxLayout>

namespace CutCell::ui {
namespace {

using cutcell::Job;
using cutcell::PipeSpec;

} // namespace

PipesForm::PipesForm(JobEditor* editor, QWidget* parent) : JobForm(editor, parent) {
    const auto pipeBox = [this](const QString& title, const std::string& prefix,
                                PipeSpec Job::*member) {
        auto* box = new QGroupBox(title, this);
        auto* f = new QFormLayout(box);
        addRow(f, tr("Outer radius"),
               bindDouble(prefix + ".radius_mm", 3,
                          [member](Job& j) -> double& { return (j.*member).radius_mm; }),
               "mm");
        addRow(f, tr("Wall thickness"),
               bindDouble(prefix + ".wall_mm", 3,
                          [member](Job& j) -> double& { return (j.*member).wall_mm; }),
               "mm");
        addRow(f, tr("Length"),
               bindDouble(prefix + ".length_mm", 1,
                          [member](Job& j) -> double& { return (j.*member).length_mm; }),
               "mm");
        return box;
    };
    mainLayout()->addWidget(pipeBox(tr("Main pipe (run)"), "main_pipe", &Job::main_pipe));
    mainLayout()->addWidget(pipeBox(tr("Branch pipe"), "branch_pipe", &Job::branch_pipe));

    auto* joint = new QGroupBox(tr("Intersection"), this);
    auto* f = new QFormLayout(joint);
    addRow(f, tr("Angle between axes"),
           bindDouble("angle_deg", 2, [](Job& j) -> double& { return j.angle_deg; }), "deg");
    addRow(f, tr("Eccentricity"),
           bindDouble("eccentricity_mm", 2, [](Job& j) -> double& { return j.eccentricity_mm; }),
           "mm");
    mainLayout()->addWidget(joint);
    mainLayout()->addStretch(1);
}

} // namespace CutCell::ui
