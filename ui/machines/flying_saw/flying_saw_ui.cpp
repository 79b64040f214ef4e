#include "ui/machines/flying_saw/flying_saw_ui.h"

#include "core/machines/flying_saw/flying_saw_module.h"
#include "ui/machines/flying_saw/flying_saw_forms.h"

#include <QObject>

#ifdef CUTCELL_HAVE_PLOTS
#include "ui/machines/flying_saw/flying_saw_figures.h"
#endif
#ifdef CUTCELL_HAVE_VIEW3D
#include "ui/machines/flying_saw/flying_saw_scene.h"
#endif

namespace CutCell::ui {

std::string FlyingSawUi::id() const {
    return cutcell::kFlyingSawId;
}

QString FlyingSawUi::title() const {
    return QObject::tr("Flying saw on a welded-pipe line (carriage, turntable, 2 blade feeds)");
}

std::vector<FormPage> FlyingSawUi::formPages() const {
    std::vector<FormPage> pages{
        {QObject::tr("Tube && line"),
         [](JobEditor* e) -> JobForm* { return new FlyingSawTubeLineForm(e); }},
        {QObject::tr("Carriage && saw"),
         [](JobEditor* e) -> JobForm* { return new FlyingSawCarriageSawForm(e); }}};
#ifdef CUTCELL_HAVE_PLOTS
    pages.push_back({QObject::tr("Cycle && cuts"),
                     [](JobEditor* e) -> JobForm* { return new FlyingSawFiguresForm(e); }});
#endif
    return pages;
}

std::vector<std::pair<std::string, QString>> FlyingSawUi::unusedCommonFields() const {
    const QString why = QObject::tr("The flying saw cuts the tube of its line across: its tube, "
                                    "line and lengths are set on the Tube & line page.");
    return pipeJointFields(why);
}

bool FlyingSawUi::buildScene(const cutcell::Job& job, const cutcell::MachinePlan& plan,
                             cutcell::view3d::SceneModel* out, QString* why) const {
#ifdef CUTCELL_HAVE_VIEW3D
    return sceneOrWhy([&] { return cutcell::view3d::buildFlyingSawScene(job, plan); }, out, why);
#else
    (void)job, (void)plan, (void)out;
    if (why) *why = QObject::tr("3D view not built in this configuration.");
    return false;
#endif
}

} // namespace CutCell::ui
