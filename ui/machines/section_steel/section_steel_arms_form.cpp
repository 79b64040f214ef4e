#include "ui/machines/section_steel/section_steel_arms_form.h"

#include "core/machines/section_steel/section_steel_section.h"
#include "core/machines/section_steel/section_steel_spec.h"
#include "ui/forms/edited_spec.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

#include <string>

namespace CutCell::ui {

using cutcell::Job;
using cutcell::section_steel::kSteelAxes;
using cutcell::section_steel::SectionSteelSpec;

namespace {

SectionSteelSpec& spec(Job& j) {
    return CutCell::ui::editedSpec<SectionSteelSpec>(j); // a scratch spec for another machine's job
}

std::string indexed(const std::string& key, size_t i) {
    return key + "[" + std::to_string(i) + "]";
}

} // namespace

SectionSteelArmsForm::SectionSteelArmsForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    // One row per key: label, unit and decimals from the section's table.
    const auto row = [this](QFormLayout* form, const char* key) {
        addSectionRow(form, sectionField(cutcell::section_steel::sectionSteelFields(), key), &spec);
    };
    auto* motion = new QGroupBox(tr("Motion"), this);
    auto* fm = new QFormLayout(motion);
    row(fm, "motion.speed_mm_s");
    row(fm, "motion.ramp_s");
    row(fm, "motion.knot_spacing_mm");
    row(fm, "motion.reorient_deg_s");
    row(fm, "motion.blend_mm");
    row(fm, "motion.torch_length_mm");
    row(fm, "motion.torch_radius_mm");
    row(fm, "motion.max_lean_deg");
    mainLayout()->addWidget(motion);

    // Joint rows: limits and park position (deg) of each joint of an arm.
    const auto jointGrid = [this](QGroupBox* box, const std::string& arm, size_t joints,
                                  size_t firstAxis, auto limit) {
        auto* grid = new QGridLayout;
        grid->addWidget(new QLabel(tr("Joint"), box), 0, 0);
        grid->addWidget(new QLabel(tr("min (deg)"), box), 0, 1);
        grid->addWidget(new QLabel(tr("max (deg)"), box), 0, 2);
        grid->addWidget(new QLabel(tr("park (deg)"), box), 0, 3);
        for (size_t i = 0; i < joints; ++i) {
            const std::string k = indexed(arm + ".limits_deg", i);
            const int gridRow = static_cast<int>(i) + 1;
            grid->addWidget(new QLabel(QStringLiteral("θ%1").arg(i + 1), box), gridRow, 0);
            grid->addWidget(
                bindDouble(k + ".min_deg", 1,
                           [limit, i](Job& j) -> double& { return limit(spec(j), i).min_deg; }),
                gridRow, 1);
            grid->addWidget(
                bindDouble(k + ".max_deg", 1,
                           [limit, i](Job& j) -> double& { return limit(spec(j), i).max_deg; }),
                gridRow, 2);
            const size_t axis = firstAxis + i;
            grid->addWidget(
                bindDouble(indexed("park_deg", axis), 1,
                           [axis](Job& j) -> double& { return spec(j).park_deg[axis]; }),
                gridRow, 3);
        }
        return grid;
    };

    auto* path =
        new QGroupBox(tr("Path arm (3R in the cut plane, joint axes along the bar)"), this);
    auto* vp = new QVBoxLayout(path);
    auto* fp = new QFormLayout;
    row(fp, "path_arm.base_y_mm");
    row(fp, "path_arm.base_z_mm");
    for (size_t i = 0; i < 3; ++i)
        addRow(fp, tr("Link a%1").arg(i + 1),
               bindDouble(indexed("path_arm.links_mm", i), 1,
                          [i](Job& j) -> double& { return spec(j).path_links_mm[i]; }),
               "mm");
    vp->addLayout(fp);
    vp->addLayout(
        jointGrid(path, "path_arm", 3, 0,
                  [](SectionSteelSpec& s, size_t i) -> cutcell::section_steel::ArmJointLimit& {
                      return s.path_limits[i];
                  }));
    mainLayout()->addWidget(path);

    auto* groove =
        new QGroupBox(tr("Groove arm (5-DOF, modified DH; bevel head at the nozzle)"), this);
    auto* vg = new QVBoxLayout(groove);
    auto* fg = new QFormLayout;
    row(fg, "groove_arm.base_x_mm");
    row(fg, "groove_arm.base_y_mm");
    row(fg, "groove_arm.base_z_mm");
    vg->addLayout(fg);
    vg->addLayout(
        jointGrid(groove, "groove_arm", 5, 3,
                  [](SectionSteelSpec& s, size_t i) -> cutcell::section_steel::ArmJointLimit& {
                      return s.groove_limits[i];
                  }));
    mainLayout()->addWidget(groove);
    mainLayout()->addStretch(1);
}

SectionSteelDrivesForm::SectionSteelDrivesForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    auto* note = new QLabel(tr("Simulated drives: a PID on the joint error (torque out, filtered "
                               "derivative) and a joint plant (inertia, viscous friction, "
                               "torque limit) per axis. Axes 0..2: path arm, 3..7: groove arm."),
                            this);
    note->setWordWrap(true);
    mainLayout()->addWidget(note);
    struct Column {
        const char* key;
        QString title;
        int decimals;
        double& (*ref)(SectionSteelSpec&, size_t);
    };
    const Column columns[] = {
        {"kp_nm_per_rad", tr("Kp (N m/rad)"), 1,
         [](SectionSteelSpec& s, size_t i) -> double& { return s.controller[i].kp; }},
        {"ki_nm_per_rad_s", tr("Ki (N m/(rad s))"), 1,
         [](SectionSteelSpec& s, size_t i) -> double& { return s.controller[i].ki; }},
        {"kd_nm_s_per_rad", tr("Kd (N m s/rad)"), 2,
         [](SectionSteelSpec& s, size_t i) -> double& { return s.controller[i].kd; }},
        {"tau_f_s", tr("τ_f (s)"), 4,
         [](SectionSteelSpec& s, size_t i) -> double& { return s.controller[i].tau_f; }},
        {"inertia_kg_m2", tr("J (kg m²)"), 3,
         [](SectionSteelSpec& s, size_t i) -> double& { return s.plant[i].inertia_kg_m2; }},
        {"viscous_nm_s_per_rad", tr("b (N m s/rad)"), 2,
         [](SectionSteelSpec& s, size_t i) -> double& { return s.plant[i].viscous_nm_s_per_rad; }},
        {"torque_limit_nm", tr("τ max (N m)"), 1,
         [](SectionSteelSpec& s, size_t i) -> double& { return s.plant[i].torque_limit_nm; }}};
    // Two tables, the controller's four columns and the plant's three: seven in one were
    // 726 px wide, the pane at 1280x720 shows 438 (the units were cut at its edge).
    const char* const names[kSteelAxes] = {"path θ1",   "path θ2",   "path θ3",   "groove θ1",
                                           "groove θ2", "groove θ3", "groove θ4", "groove θ5"};
    const auto table = [&](const QString& title, int first, int count) {
        auto* box = new QGroupBox(title, this);
        auto* grid = new QGridLayout(box);
        for (int c = 0; c < count; ++c) {
            auto* head = new QLabel(columns[first + c].title, box);
            head->setWordWrap(true); // "Ki" over "(N m/(rad s))"
            grid->addWidget(head, 0, c + 1);
        }
        for (size_t i = 0; i < kSteelAxes; ++i) {
            const int row = static_cast<int>(i) + 1;
            grid->addWidget(new QLabel(QString::fromUtf8(names[i]), box), row, 0);
            for (int c = 0; c < count; ++c) {
                const auto ref = columns[first + c].ref;
                grid->addWidget(bindDouble(indexed("drives", i) + "." + columns[first + c].key,
                                           columns[first + c].decimals,
                                           [ref, i](Job& j) -> double& { return ref(spec(j), i); }),
                                row, c + 1);
            }
        }
        mainLayout()->addWidget(box);
    };
    table(tr("Drives: controller"), 0, 4);
    table(tr("Drives: joint plant"), 4, 3);
    mainLayout()->addStretch(1);
}

} // namespace CutCell::ui
