#include "ui/machines/quick_return/quick_return_ui.h"

#include "ui/machines/quick_return/quick_return_form.h"

#include <QObject>

#ifdef CUTCELL_HAVE_PLOTS
#include "ui/machines/quick_return/quick_return_figures.h"
#include "ui/machines/quick_return/quick_return_tracking_page.h"
#endif
#ifdef CUTCELL_HAVE_VIEW3D
#include "ui/machines/quick_return/quick_return_scene.h"
#endif

namespace CutCell::ui {

QString QuickReturnUi::title() const {
    return QObject::tr("Quick-return (Whitworth) cutter: crank in torque mode");
}

std::vector<FormPage> QuickReturnUi::formPages() const {
    std::vector<FormPage> pages{
        {QObject::tr("Mechanism"),
         [](JobEditor* e) -> JobForm* { return new QuickReturnMechanismForm(e); }},
        {QObject::tr("Controller"),
         [](JobEditor* e) -> JobForm* { return new QuickReturnControllerForm(e); }}};
#ifdef CUTCELL_HAVE_PLOTS
    pages.push_back({QObject::tr("Cut figures"),
                     [](JobEditor* e) -> JobForm* { return new QuickReturnFiguresForm(e); }});
    pages.push_back({QObject::tr("Experiment 1"),
                     [](JobEditor* e) -> JobForm* { return new QuickReturnTrackingForm(e); }});
#endif
    return pages;
}

std::vector<std::pair<std::string, QString>> QuickReturnUi::unusedCommonFields() const {
    const QString why =
        QObject::tr("The quick-return cutter planes a flat workpiece along its stroke: no pipes, "
                    "its cut is set on the Mechanism page.");
    return pipeJointFields(why);
}

bool QuickReturnUi::buildScene(const cutcell::Job& job, const cutcell::MachinePlan&,
                               cutcell::view3d::SceneModel* out, QString* why) const {
#ifdef CUTCELL_HAVE_VIEW3D
    return sceneOrWhy([&] { return cutcell::view3d::buildQuickReturnScene(job); }, out, why);
#else
    (void)job, (void)out;
    if (why) *why = QObject::tr("3D view not built in this configuration.");
    return false;
#endif
}

} // namespace CutCell::ui
