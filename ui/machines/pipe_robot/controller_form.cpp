#include "ui/machines/pipe_robot/controller_form.h"
#include "core/job/drive_fields.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "core/machines/pipe_robot/pipe_robot_tuning.h"
#include "ui/forms/edited_spec.h"
#include "ui/shown_number.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <limits>

namespace CutCell::ui {

using cutcell::ArmLinkRow;
using cutcell::DriveTrainRow;
using cutcell::Job;
using cutcell::JointPlantParams;
using cutcell::PidGains;
using cutcell::PipeRobotSpec;
using cutcell::PlantModel;

namespace {

QTableWidget* makeTable(QWidget* parent, const QStringList& rows) {
    auto* t = new QTableWidget(static_cast<int>(rows.size()), 0, parent);
    t->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    t->setVerticalHeaderLabels(rows);
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    t->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->setSelectionMode(QAbstractItemView::NoSelection);
    t->setFocusPolicy(Qt::NoFocus);
    // As tall as its rows: no empty band, no scroll bar.
    t->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    t->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    t->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    return t;
}

QLabel* hint(const QString& text, QWidget* parent) {
    auto* l = new QLabel(text, parent);
    l->setObjectName("hint");
    l->setWordWrap(true);
    return l;
}

} // namespace

ControllerForm::ControllerForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent), cancel_(std::make_shared<std::atomic<bool>>(false)) {
    const QStringList axisNames = {tr("0 chuck"), tr("1 base"),  tr("2 shoulder"),
                                   tr("3 elbow"), tr("4 wrist"), tr("5 roll")};
    QStringList linkNames;
    for (int i = 1; i <= cutcell::kArmJointCount; ++i)
        linkNames << tr("link %1").arg(i);

    auto* pidBox = new QGroupBox(tr("PID with first-order filter, per joint"), this);
    auto* pv = new QVBoxLayout(pidBox);
    auto* pid = makeTable(pidBox, axisNames);
    pid->setObjectName("pidTable");
    // Headers, units and decimals from the drive's tables (core/job/drive_fields.h).
    bindRowTable<PidGains>(
        pid, cutcell::pidGainFields(), "controller",
        [](Job& j, size_t i) -> PidGains& { return editedSpec<PipeRobotSpec>(j).controller[i]; });
    pv->addWidget(pid);
    pv->addWidget(hint(tr("C(s) = (Kd s + Kp + Ki/s) / (tau_f s + 1); output in N m."), pidBox));
    auto* tuneRow = new QHBoxLayout;
    tuneButton_ = new QPushButton(tr("Tune (SIMC)"), pidBox);
    tuneButton_->setObjectName("tuneButton");
    tuneButton_->setToolTip(
        tr("Kp, Ki and Kd of every joint by Skogestad's SIMC rules (tight: tau_c = theta) from "
           "the joint's inertia and viscous friction: the rigid-body model at the cut's mean "
           "pose, or the linear plant rows. tau_f stays."));
    connect(tuneButton_, &QPushButton::clicked, this, &ControllerForm::tune);
    tuneRow->addWidget(tuneButton_);
    tuneRow->addStretch(1);
    pv->addLayout(tuneRow);
    tuneStatus_ = hint(QString(), pidBox);
    tuneStatus_->setObjectName("tuneStatus");
    tuneStatus_->hide();
    pv->addWidget(tuneStatus_);
    mainLayout()->addWidget(pidBox);

    auto* modelBox = new QGroupBox(tr("Mechanics of the simulated drives"), this);
    auto* mf = new QFormLayout(modelBox);
    auto* model = bindChoice(
        "plant_model", {tr("Rigid body"), tr("Linear plant")},
        [](const Job& j) {
            return editedSpec<PipeRobotSpec>(j).plant_model == PlantModel::RigidBody ? 0 : 1;
        },
        [](Job& j, int i) {
            editedSpec<PipeRobotSpec>(j).plant_model =
                i == 0 ? PlantModel::RigidBody : PlantModel::Linear;
        });
    model->setObjectName("plantModel");
    addRow(mf, tr("Plant model"), model, QString());
    auto* gravity =
        bindBool("gravity_feedforward", tr("Gravity feed-forward"),
                 [](Job& j) -> bool& { return editedSpec<PipeRobotSpec>(j).gravity_feedforward; });
    gravity->setObjectName("gravityFeedforward");
    mf->addRow(gravity);
    mf->addRow(hint(tr("Rigid body: the arm's links and the drive trains below, coupled. "
                       "Linear: one inertia and viscous friction per joint."),
                    modelBox));
    mainLayout()->addWidget(modelBox);

    auto* plantBox = new QGroupBox(tr("Joint plant (linear model)"), this);
    auto* lv = new QVBoxLayout(plantBox);
    auto* plant = makeTable(plantBox, axisNames);
    plant->setObjectName("plantTable");
    bindRowTable<JointPlantParams>(plant, cutcell::jointPlantFields(), "plant",
                                   [](Job& j, size_t i) -> JointPlantParams& {
                                       return editedSpec<PipeRobotSpec>(j).plant[i];
                                   });
    lv->addWidget(plant);
    mainLayout()->addWidget(plantBox);

    // The links' ten numbers in three tables of a few columns each: the pane is ~424 px wide.
    auto* linkBox = new QGroupBox(tr("Arm links (rigid-body model)"), this);
    auto* kv = new QVBoxLayout(linkBox);
    const auto linkRow = [](Job& j, size_t i) -> ArmLinkRow& {
        return editedSpec<PipeRobotSpec>(j).links[i];
    };
    const std::span<const cutcell::RowField<ArmLinkRow>> linkFields = cutcell::armLinkFields();
    const struct {
        const char* name;
        size_t first, count;
    } linkTables[] = {
        {"linkMassTable", 0, 4}, {"linkInertiaTable", 4, 3}, {"linkProductsTable", 7, 3}};
    for (const auto& part : linkTables) {
        auto* table = makeTable(linkBox, linkNames);
        table->setObjectName(part.name);
        bindRowTable<ArmLinkRow>(table, linkFields.subspan(part.first, part.count), "robot.links",
                                 linkRow);
        kv->addWidget(table);
    }
    kv->addWidget(hint(tr("Centre of mass in the link's frame; inertia tensor about the centre "
                          "of mass, in the same frame."),
                       linkBox));
    mainLayout()->addWidget(linkBox);

    auto* driveBox = new QGroupBox(tr("Drive trains (rigid-body model)"), this);
    auto* dv = new QVBoxLayout(driveBox);
    // Gear and rotor, then friction and torque limit: five columns do not fit the pane.
    const auto driveRow = [](Job& j, size_t i) -> DriveTrainRow& {
        return editedSpec<PipeRobotSpec>(j).drives[i];
    };
    const std::span<const cutcell::RowField<DriveTrainRow>> driveFields =
        cutcell::driveTrainFields();
    const struct {
        const char* name;
        size_t first, count;
    } driveTables[] = {{"driveTable", 0, 2}, {"driveFrictionTable", 2, 3}};
    for (const auto& part : driveTables) {
        auto* table = makeTable(driveBox, axisNames);
        table->setObjectName(part.name);
        bindRowTable<DriveTrainRow>(table, driveFields.subspan(part.first, part.count),
                                    "robot.drives", driveRow);
        dv->addWidget(table);
    }
    dv->addWidget(hint(tr("Rotor inertia on the motor side; friction and torque limit on the "
                          "joint side."),
                       driveBox));
    mainLayout()->addWidget(driveBox);

    auto* chuckBox = new QGroupBox(tr("Chuck (rigid-body model)"), this);
    auto* cf = new QFormLayout(chuckBox);
    addRow(cf, tr("Chuck inertia"),
           bindDouble(
               "robot.chuck.inertia_kg_m2", 4,
               [](Job& j) -> double& { return editedSpec<PipeRobotSpec>(j).chuck.inertia_kg_m2; }),
           displayUnit("kg m^2"));
    addRow(cf, tr("Pipe density"),
           bindDouble("robot.chuck.pipe_density_kg_m3", 0,
                      [](Job& j) -> double& {
                          return editedSpec<PipeRobotSpec>(j).chuck.pipe_density_kg_m3;
                      }),
           displayUnit("kg/m^3"));
    cf->addRow(
        hint(tr("The pipe in the chuck turns with it: the chuck's inertia adds it."), chuckBox));
    mainLayout()->addWidget(chuckBox);
    mainLayout()->addStretch(1);

    const auto newJob = [this] {
        ++generation_;
        tuneStatus_->hide();
    };
    connect(editor, &JobEditor::jobReset, this, newJob);
    connect(editor, &JobEditor::edited, this, [this] { ++generation_; });
}

ControllerForm::~ControllerForm() {
    cancel_->store(true); // a tuning still planning stops; its result is dropped
}

void ControllerForm::tune() {
    const auto say = [this](const QString& text) {
        tuneStatus_->setText(text);
        tuneStatus_->show();
    };
    const std::string firstKey = cutcell::rowKey("controller", 0) + ".kp_nm_per_rad";
    if (const QString why = editor()->lockReason(firstKey); !why.isEmpty()) {
        say(tr("Not tuned: %1").arg(why));
        return;
    }
    if (!editor()->valid()) {
        say(tr("Not tuned: the job has invalid values; correct the marked fields first."));
        return;
    }
    tuneButton_->setEnabled(false);
    say(tr("Tuning: planning the cut for its mean pose..."));
    const quint64 generation = generation_;
    const Job job = editor()->job();
    const std::shared_ptr<std::atomic<bool>> cancel = cancel_;
    auto* watcher = new QFutureWatcher<cutcell::PipeRobotTuning>(this);
    connect(
        watcher, &QFutureWatcher<cutcell::PipeRobotTuning>::finished, this,
        [this, watcher, generation, say] {
            watcher->deleteLater();
            tuneButton_->setEnabled(true);
            const cutcell::PipeRobotTuning t = watcher->result();
            if (generation != generation_) {
                say(tr("Not tuned: the job changed while tuning; tune again."));
                return;
            }
            if (!t.outcome.ok()) {
                say(tr("Not tuned: %1").arg(QString::fromStdString(t.outcome.message)));
                return;
            }
            // As if typed into the table: each gain through the editor's gate, marked
            // modified, in the audit trail, saved with the job.
            const auto fields = cutcell::pidGainFields();
            for (size_t i = 0; i < cutcell::kAxisCount; ++i)
                for (const auto& f : fields) {
                    PidGains g = t.gains[i];
                    double& v = f.number(g);
                    if (&v == &g.tau_f) continue;
                    const std::string key =
                        cutcell::rowKey("controller", i) + "." + std::string(f.key);
                    if (auto* box = qobject_cast<QDoubleSpinBox*>(fieldFor(key))) box->setValue(v);
                }
            double gm = std::numeric_limits<double>::infinity();
            QStringList lines;
            const QStringList names = {tr("0 chuck"), tr("1 base"),  tr("2 shoulder"),
                                       tr("3 elbow"), tr("4 wrist"), tr("5 roll")};
            for (size_t i = 0; i < cutcell::kAxisCount; ++i) {
                const cutcell::SimcTuning& x = t.axes[i].simc;
                gm = std::min(gm, t.axes[i].margins.gain_margin);
                lines << tr("%1: J = %2 kg m², b = %3 N m s/rad, theta = %4 ms, Kc = %5 N m/rad, "
                            "tau_I = %6 ms, tau_D = %7 ms, gain margin %8")
                             .arg(names[static_cast<int>(i)], shownNumber(x.inertia_kg_m2, 5),
                                  shownNumber(x.viscous_nm_s_per_rad, 3),
                                  shownNumber(x.theta_s * 1e3, 2), shownNumber(x.kc, 1),
                                  shownNumber(x.tau_i_s * 1e3, 1), shownNumber(x.tau_d_s * 1e3, 1),
                                  shownNumber(t.axes[i].margins.gain_margin, 1));
            }
            const QString model = t.model == PlantModel::RigidBody
                                      ? tr("rigid body at the cut's mean pose")
                                      : tr("linear plant rows");
            say(tr("SIMC gains written (%1): tau_c = theta = %2 ms, gain margin %3 or more.")
                    .arg(model, shownNumber(t.axes[0].simc.tau_c_s * 1e3, 2), shownNumber(gm, 1)));
            tuneStatus_->setToolTip(lines.join('\n'));
        });
    watcher->setFuture(QtConcurrent::run([job, cancel] {
        cutcell::PlanOptions options;
        options.cancel = cancel.get();
        try {
            return cutcell::tunePipeRobot(job, 0, options);
        } catch (const std::exception& e) {
            cutcell::PipeRobotTuning failed;
            failed.outcome = cutcell::Outcome::refuse(e.what());
            return failed;
        }
    }));
}

} // namespace CutCell::ui
