#include "ui/window_host.h"

#include "ui/forms/parameter_tabs.h"
#include "ui/job_document.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/panels/event_log_panel.h"

#include <QByteArray>
#include <QTimer>

namespace CutCell::ui {

WindowHost::WindowHost(EngineRigFactory factory, QObject* parent)
    : QObject(parent), factory_(std::move(factory)) {
    adopt(std::make_unique<MainWindow>(factory_));
}

WindowHost::~WindowHost() = default;

void WindowHost::adopt(std::unique_ptr<MainWindow> window) {
    window_ = std::move(window);
    // Queued: the request comes from the old window's own menu, which must not be destroyed
    // under its own signal.
    connect(
        window_.get(), &MainWindow::languageChangeRequested, this,
        [this](const QString& code) { changeLanguage(code); }, Qt::QueuedConnection);
}

bool WindowHost::changeLanguage(const QString& code, QString* why) {
    QString reason;
    if (!window_->canRebuild(&reason)) {
        window_->eventLog()->add(cutcell::Severity::Warning,
                                 tr("The language was not changed: %1.").arg(reason));
        if (why) *why = reason;
        return false;
    }
    const QString before = shownLanguage();
    if (!applyGuiLanguage(code, &reason)) {
        window_->eventLog()->add(cutcell::Severity::Warning,
                                 tr("The language was not changed: %1.").arg(reason));
        applyGuiLanguage(before);
        if (why) *why = reason;
        return false;
    }
    rememberLanguage(code);

    const MainWindow::Carry carry = window_->carry();
    const bool shown = window_->isVisible();
    const QByteArray geometry = window_->saveGeometry();
    const QSize size = window_->size();
    const bool driveWasOn = carry.drivesEnabled;
    window_.reset(); // the old rig goes first: its drives are disabled
    adopt(std::make_unique<MainWindow>(factory_));
    window_->takeOver(carry);
    if (shown) {
        window_->restoreGeometry(geometry);
        window_->show();
    } else {
        window_->resize(size);
    }
    window_->eventLog()->add(cutcell::Severity::Info,
                             tr("Language: %1.").arg(window_->languageName()));
    if (driveWasOn)
        window_->eventLog()->add(
            cutcell::Severity::Warning,
            tr("The drives were disabled for the change of language: press Enable and Home."));
    emit windowRebuilt(window_.get());
    return true;
}

} // namespace CutCell::ui
