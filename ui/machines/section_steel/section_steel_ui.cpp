#include "ui/machines/section_steel/section_steel_ui.h"

#include "core/machine/machine_module.h"
#include "ui/machines/section_steel/section_steel_arms_form.h"
#include "ui/machines/section_steel/section_steel_form.h"

#include <QObject>

#ifdef CUTCELL_HAVE_VIEW3D
#include "core/machines/section_steel/section_steel_planner.h"
#include "ui/machines/section_steel/section_steel_scene.h"
#endif

namespace CutCell::ui {

QString SectionSteelUi::title() const {
    return QObject::tr("Section-steel cutter (3R path arm + 5-DOF groove arm)");
}

std::vector<FormPage> SectionSteelUi::formPages() const {
    return {{QObject::tr("Section"),
             [](JobEditor* e) -> JobForm* { return new SectionSteelSectionForm(e); }},
            {QObject::tr("End cut"),
             [](JobEditor* e) -> JobForm* { return new SectionSteelEndCutForm(e); }},
            {QObject::tr("Motion && arms"),
             [](JobEditor* e) -> JobForm* { return new SectionSteelArmsForm(e); }},
            {QObject::tr("Drives"),
             [](JobEditor* e) -> JobForm* { return new SectionSteelDrivesForm(e); }}};
}

std::vector<std::pair<std::string, QString>> SectionSteelUi::unusedCommonFields() const {
    const QString why = QObject::tr("The section-steel cutter cuts the end of a structural "
                                    "section: no pipes; its section, cut and speed are set on "
                                    "the Section, End cut and Motion pages.");
    return pipeJointFields(why);
}

bool SectionSteelUi::buildScene(const cutcell::Job& job, const cutcell::MachinePlan& plan,
                                cutcell::view3d::SceneModel* out, QString* why) const {
#ifdef CUTCELL_HAVE_VIEW3D
    // The module's plan (feasible or not: an infeasible cut is drawn with its problem).
    const auto* steel = static_cast<const cutcell::section_steel::SteelPlan*>(plan.data.get());
    return sceneOrWhy([&] { return cutcell::view3d::buildSectionSteelScene(job, steel); }, out,
                      why);
#else
    (void)job, (void)plan, (void)out;
    if (why) *why = QObject::tr("3D view not built in this configuration.");
    return false;
#endif
}

} // namespace CutCell::ui
