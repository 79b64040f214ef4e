#include "ui/machines/pipe_robot/controller_form.h"
#include "core/job/drive_fields.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "ui/forms/edited_spec.h"

#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::Job;
using cutcell::JointPlantParams;
using cutcell::PidGains;

namespace {

const QStringList kAxisNames = {"0 chuck", "1 base", "2 shoulder", "3 elbow", "4 wrist", "5 roll"};

QTableWidget* makeTable(QWidget* parent) {
    auto* t = new QTableWidget(cutcell::kAxisCount, 0, parent);
    t->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    t->setVerticalHeaderLabels(kAxisNames);
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    t->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->setSelectionMode(QAbstractItemView::NoSelection);
    t->setFocusPolicy(Qt::NoFocus);
    // As tall as its six rows: no empty band, no scroll bar.
    t->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    t->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    t->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    return t;
}

} // namespace

ControllerForm::ControllerForm(JobEditor* editor, QWidget* parent) : JobForm(editor, parent) {
    auto* pidBox = new QGroupBox(tr("PID with first-order filter, per joint"), this);
    auto* pv = new QVBoxLayout(pidBox);
    auto* pid = makeTable(pidBox);
    pid->setObjectName("pidTable");
    // Headers, units and decimals from the drive's tables (core/job/drive_fields.h).
    bindRowTable<PidGains>(pid, cutcell::pidGainFields(), "controller",
                           [](Job& j, size_t i) -> PidGains& {
                               return editedSpec<cutcell::PipeRobotSpec>(j).controller[i];
                           });
    pv->addWidget(pid);
    auto* law = new QLabel(tr("C(s) = (Kd s + Kp + Ki/s) / (tau_f s + 1); output in N m."), pidBox);
    law->setObjectName("hint");
    pv->addWidget(law);
    mainLayout()->addWidget(pidBox);

    auto* plantBox = new QGroupBox(tr("Joint plant (simulated drives)"), this);
    auto* lv = new QVBoxLayout(plantBox);
    auto* plant = makeTable(plantBox);
    plant->setObjectName("plantTable");
    bindRowTable<JointPlantParams>(plant, cutcell::jointPlantFields(), "plant",
                                   [](Job& j, size_t i) -> JointPlantParams& {
                                       return editedSpec<cutcell::PipeRobotSpec>(j).plant[i];
                                   });
    lv->addWidget(plant);
    mainLayout()->addWidget(plantBox);
    mainLayout()->addStretch(1);
}

} // namespace CutCell::ui
