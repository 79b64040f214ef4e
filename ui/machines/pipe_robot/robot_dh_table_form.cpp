#include "ui/machines/pipe_robot/robot_dh_table_form.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "ui/forms/edited_spec.h"

#include <QDoubleSpinBox>
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
    auto* table = new QTableWidget(cutcell::kAxisCount, 6, box);
    table->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    table->setObjectName("dhTable");
    table->setHorizontalHeaderLabels({tr("alpha\n[deg]"), tr("a\n[mm]"), tr("d\n[mm]"),
                                      tr("offset\n[deg]"), tr("min\n[deg]"), tr("max\n[deg]")});
    table->setVerticalHeaderLabels({tr("0 chuck"), tr("1 base"), tr("2 shoulder"), tr("3 elbow"),
                                    tr("4 wrist"), tr("5 roll")});
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->setFocusPolicy(Qt::NoFocus);

    struct Column {
        const char* key;
        int decimals;
        double DhRow::*member;
    };
    const Column columns[] = {
        {"alpha_deg", 1, &DhRow::alpha_deg}, {"a_mm", 1, &DhRow::a_mm},
        {"d_mm", 1, &DhRow::d_mm},           {"theta_offset_deg", 1, &DhRow::theta_offset_deg},
        {"min_deg", 1, &DhRow::min_deg},     {"max_deg", 1, &DhRow::max_deg}};
    for (int r = 0; r < cutcell::kAxisCount; ++r) {
        for (int c = 0; c < 6; ++c) {
            const auto& col = columns[c];
            const auto row = static_cast<size_t>(r);
            const std::string key = "robot.dh[" + std::to_string(r) + "]." + col.key;
            auto* w = bindDouble(key, col.decimals, [row, m = col.member](Job& j) -> double& {
                return editedSpec<cutcell::PipeRobotSpec>(j).dh[row].*m;
            });
            w->setFrame(false);
            table->setCellWidget(r, c, w);
        }
    }
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
