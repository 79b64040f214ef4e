#include "ui/machines/pipe_robot/robot_dh_table_form.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "ui/forms/edited_spec.h"

#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::DhRow;
using cutcell::Job;

RobotDhTableForm::RobotDhTableForm(JobEditor* editor, QWidget* parent) : JobForm(editor, parent) {
    auto* box = new QGroupBox(tr("Denavit-Hartenberg table and joint limits"), this);
    auto* v = new QVBoxLayout(box);
    auto* table = new QTableWidget(cutcell::kAxisCount, 0, box);
    table->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    table->setObjectName("dhTable");
    table->setVerticalHeaderLabels({tr("0 chuck"), tr("1 base"), tr("2 shoulder"), tr("3 elbow"),
                                    tr("4 wrist"), tr("5 roll")});
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->setFocusPolicy(Qt::NoFocus);

    // The columns of robot.dh[] rows: header, unit and decimals from the table.
    bindRowTable<DhRow>(table, cutcell::dhRowFields(), "robot.dh", [](Job& j, size_t i) -> DhRow& {
        return editedSpec<cutcell::PipeRobotSpec>(j).dh[i];
    });
    // As tall as its six rows: no empty band, no scroll bar.
    table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    v->addWidget(table);
    auto* note = new QLabel(
        tr("Row 0 is the pipe chuck: its d is the distance from the robot base to the cut "
           "centre. The analytic inverse kinematics needs the seed arm's structure "
           "(alpha = 90, 0, 0, 90, 0 deg for rows 1..5)."),
        box);
    note->setObjectName("hint");
    note->setWordWrap(true);
    v->addWidget(note);
    mainLayout()->addWidget(box);
    mainLayout()->addStretch(1);
}

} // namespace CutCell::ui
