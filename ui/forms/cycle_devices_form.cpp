#include "ui/forms/cycle_devices_form.h"
#include "ui/machine/machine_ui.h"
#include "ui/machine/machine_ui_registry.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::DeviceKind;
using cutcell::Job;
using cutcell::StopCategory;

CycleDevicesForm::CycleDevicesForm(JobEditor* editor, QWidget* parent) : JobForm(editor, parent) {
    auto* cycle = new QGroupBox(tr("Control cycle"), this);
    auto* c = new QFormLayout(cycle);
    addRow(c, tr("Cycle period"),
           bindDouble("sim.period_s", 4, [](Job& j) -> double& { return j.sim.period_s; }), "s");
    addRow(c, tr("Simulation duration"),
           bindDouble("sim.duration_s", 1, [](Job& j) -> double& { return j.sim.duration_s; }),
           "s");
    mainLayout()->addWidget(cycle);

    auto* engine = new QGroupBox(tr("Safety and feed hold"), this);
    auto* e = new QFormLayout(engine);
    addRow(e, tr("E-stop category"),
           bindChoice(
               "engine.estop_category",
               {tr("Cat 0: torch off, drives off at once"), tr("Cat 1: controlled stop, then off")},
               [](const Job& j) { return j.engine.estop_category == StopCategory::Cat0 ? 0 : 1; },
               [](Job& j, int i) {
                   j.engine.estop_category = i == 0 ? StopCategory::Cat0 : StopCategory::Cat1;
               }),
           {});
    addRow(e, tr("Feed hold deceleration"),
           bindDouble("engine.feed_hold_decel_s", 3,
                      [](Job& j) -> double& { return j.engine.feed_hold_decel_s; }),
           "s");
    e->addRow(tr("Torch in feed hold"),
              bindBool("engine.torch_on_during_feed_hold", tr("keep the torch on"),
                       [](Job& j) -> bool& { return j.engine.torch_on_during_feed_hold; }));
    // Each limit in the unit of the axes it governs; a machine without linear (or rotary) axes
    // has those fields greyed (ParameterTabs::applyMachine).
    addRow(e, tr("Following error limit, rotary axes"),
           bindDouble("engine.following_error_limit_deg", 3,
                      [](Job& j) -> double& { return j.engine.following_error_limit_deg; }),
           "deg");
    addRow(e, tr("Following error limit, linear axes"),
           bindDouble("engine.following_error_limit_mm", 3,
                      [](Job& j) -> double& { return j.engine.following_error_limit_mm; }),
           "mm");
    addRow(e, tr("Homing speed, rotary axes"),
           bindDouble("engine.home_speed_deg_s", 1,
                      [](Job& j) -> double& { return j.engine.home_speed_deg_s; }),
           "deg/s");
    addRow(e, tr("Homing speed, linear axes"),
           bindDouble("engine.home_speed_mm_s", 1,
                      [](Job& j) -> double& { return j.engine.home_speed_mm_s; }),
           "mm/s");
    addRow(e, tr("Run records folder"),
           bindString("engine.runs_dir", [](Job& j) -> std::string& { return j.engine.runs_dir; }),
           {});
    mainLayout()->addWidget(engine);

    auto* dev = new QGroupBox(tr("Devices"), this);
    auto* d = new QFormLayout(dev);
    addRow(d, tr("Drives"),
           bindChoice(
               "devices.kind", {tr("Simulated cell"), tr("CANopen CiA 402")},
               [](const Job& j) { return j.devices.kind == DeviceKind::Simulated ? 0 : 1; },
               [](Job& j, int i) {
                   j.devices.kind = i == 0 ? DeviceKind::Simulated : DeviceKind::CanOpen;
               }),
           {});
    addRow(d, tr("CAN plugin"),
           bindString("devices.can_plugin",
                      [](Job& j) -> std::string& { return j.devices.can_plugin; }),
           {});
    addRow(d, tr("CAN interface"),
           bindString("devices.can_interface",
                      [](Job& j) -> std::string& { return j.devices.can_interface; }),
           {});
    addRow(d, tr("Bit rate"),
           bindInt("devices.bitrate_bps", [](Job& j) -> int& { return j.devices.bitrate_bps; }),
           "bit/s");
    addRow(d, tr("Heartbeat timeout"),
           bindDouble("devices.heartbeat_timeout_ms", 0,
                      [](Job& j) -> double& { return j.devices.heartbeat_timeout_ms; }),
           "ms");

    // One row per axis (a row of six columns was wider than the form's column).
    auto* axes = new QWidget(dev);
    auto* g = new QGridLayout(axes);
    g->setContentsMargins(0, 0, 0, 0);
    g->addWidget(new QLabel(tr("Axis"), axes), 0, 0);
    g->addWidget(new QLabel(tr("Node ID"), axes), 0, 1);
    g->addWidget(new QLabel(tr("Counts/unit"), axes), 0, 2);
    g->setColumnStretch(1, 1);
    g->setColumnStretch(2, 2);
    // Rows for up to kMaxAxes axes; reloadExtra() shows the job's machine's axes only.
    for (int i = 0; i < cutcell::kMaxAxes; ++i) {
        const auto a = static_cast<size_t>(i);
        auto* head = new QLabel(QString::number(i), axes);
        head->setAlignment(Qt::AlignCenter);
        g->addWidget(head, i + 1, 0);
        auto* id = bindInt("devices.node_ids[" + std::to_string(i) + "]",
                           [a](Job& j) -> int& { return j.devices.node_ids[a]; });
        alsoMark("devices.node_ids", id);
        g->addWidget(id, i + 1, 1);
        auto* counts = bindDouble("devices.counts_per_unit[" + std::to_string(i) + "]", 0,
                                  [a](Job& j) -> double& { return j.devices.counts_per_unit[a]; });
        g->addWidget(counts, i + 1, 2);
        axisRows_.push_back({head, id, counts});
    }
    d->addRow(axes);
    auto* unit = new QLabel(tr("Counts per degree (rotary axes) or per mm (linear axes)."), dev);
    unit->setObjectName("hint");
    unit->setWordWrap(true);
    d->addRow(unit);
    mainLayout()->addWidget(dev);
    mainLayout()->addStretch(1);
}

void CycleDevicesForm::reloadExtra(const Job& job) {
    const MachineUi* machine = machineUiFor(job);
    const std::vector<AxisLabel> labels = machine ? machine->axes() : std::vector<AxisLabel>{};
    const size_t shown = machine ? labels.size() : static_cast<size_t>(cutcell::kMaxAxes);
    for (size_t i = 0; i < axisRows_.size(); ++i) {
        for (QWidget* w : axisRows_[i])
            w->setVisible(i < shown);
        if (i < labels.size())
            static_cast<QLabel*>(axisRows_[i][0])
                ->setText(QString::number(i) + QLatin1Char(' ') + labels[i].name);
    }
}

} // namespace CutCell::ui
