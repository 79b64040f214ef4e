#pragma once
// Owns the operator station's main window and rebuilds it for a change of language: every
// widget is made in the new language (the panels set their texts once, when built), with the
// job the old window held — its file, its unsaved edits and modified mark —, its geometry and
// its parameter tab. The machine must be at rest for that: the old window's rig goes (its
// drives are disabled) and the new one starts disabled, as after a start of the program.
//
// Threading contract: GUI thread only.
#include "ui/engine_rig.h"

#include <QObject>
#include <QString>

#include <memory>

namespace CutCell::ui {

class MainWindow;

class WindowHost : public QObject {
    Q_OBJECT
  public:
    explicit WindowHost(EngineRigFactory factory, QObject* parent = nullptr);
    ~WindowHost() override;

    MainWindow* window() const { return window_.get(); }
    // Rebuilds the window in `code` (see ui/language.h); false, with the reason in `why` and
    // in the window's log, while the machine is moving or for an unknown language. The
    // choice is remembered for the next start.
    bool changeLanguage(const QString& code, QString* why = nullptr);

  signals:
    void windowRebuilt(MainWindow* window);

  private:
    void adopt(std::unique_ptr<MainWindow> window);

    EngineRigFactory factory_;
    std::unique_ptr<MainWindow> window_;
};

} // namespace CutCell::ui
