#include "ui/machines/pipe_robot/controller_form.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "ui/forms/edited_spec.h"

#include <QDoubleSpinBox>
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

QTableWidget* makeTable(QWidget* parent, const QStringList& headers) {
    auto* t = new QTableWidget(cutcell::kAxisCount, static_cast<int>(headers.size()), parent);
    t->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    t->setHorizontalHeaderLabels(headers);
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
    auto* pid = makeTable(pidBox, {tr("Kp\n[N m/rad]"), tr("Ki\n[N m/(rad s)]"),
                                   tr("Kd\n[N m s/rad]"), tr("tau_f\n[s]")});
    pid->setObjectName("pidTable");
    struct Gain {
        const char* key;
        int decimals;
        double PidGains::*member;
    };
    const Gain gains[] = {{"kp_nm_per_rad", 2, &PidGains::kp},
                          {"ki_nm_per_rad_s", 1, &PidGains::ki},
                          {"kd_nm_s_per_rad", 3, &PidGains::kd},
                          {"tau_f_s", 4, &PidGains::tau_f}};
    for (int r = 0; r < cutcell::kAxisCount; ++r)
        for (int c = 0; c < 4; ++c) {
            const auto row = static_cast<size_t>(r);
            auto* w =
                bindDouble("controller[" + std::to_string(r) + "]." + gains[c].key,
                           gains[c].decimals, [row, m = gains[c].member](Job& j) -> double& {
                               return editedSpec<cutcell::PipeRobotSpec>(j).controller[row].*m;
                           });
            w->setFrame(false);
            pid->setCellWidget(r, c, w);
        }
    pv->addWidget(pid);
    auto* law = new QLabel(tr("C(s) = (Kd s + Kp + Ki/s) / (tau_f s + 1); output in N m."), pidBox);
    law->setObjectName("hint");
    pv->addWidget(law);
    mainLayout()->addWidget(pidBox);

    auto* plantBox = new QGroupBox(tr("Joint plant (simulated drives)"), this);
    auto* lv = new QVBoxLayout(plantBox);
    auto* plant = makeTable(
        plantBox, {tr("Inertia\n[kg m^2]"), tr("Viscous\n[N m s/rad]"), tr("Torque limit\n[N m]")});
    plant->setObjectName("plantTable");
    struct Param {
        const char* key;
        int decimals;
        double JointPlantParams::*member;
    };
    const Param params[] = {{"inertia_kg_m2", 4, &JointPlantParams::inertia_kg_m2},
                            {"viscous_nm_s_per_rad", 3, &JointPlantParams::viscous_nm_s_per_rad},
                            {"torque_limit_nm", 2, &JointPlantParams::torque_limit_nm}};
    for (int r = 0; r < cutcell::kAxisCount; ++r)
        for (int c = 0; c < 3; ++c) {
            const auto row = static_cast<size_t>(r);
            auto* w =
                bindDouble("plant[" + std::to_string(r) + "]." + params[c].key, params[c].decimals,
                           [row, m = params[c].member](Job& j) -> double& {
                               return editedSpec<cutcell::PipeRobotSpec>(j).plant[row].*m;
                           });
            w->setFrame(false);
            plant->setCellWidget(r, c, w);
        }
    lv->addWidget(plant);
    mainLayout()->addWidget(plantBox);
    mainLayout()->addStretch(1);
}

} // namespace CutCell::ui
