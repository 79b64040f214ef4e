#pragma once
// The main window's Language and Help menus. Language lists "System (...)", English and
// Deutsch (checked: the one shown); choosing another calls `choose` with its code (the
// window's host rebuilds the window in it). Help holds Keys, Manual (the README's operator
// sections, offline) and About (version, build, machines). No key of these menus may take F1:
// F1 is the EMERGENCY STOP.
//
// Threading contract: GUI thread only.
#include <QString>

#include <functional>

class QMenuBar;
class QWidget;

namespace CutCell::ui {

void addLanguageMenu(QMenuBar* bar, QWidget* parent, std::function<void(const QString&)> choose);
void addHelpMenu(QMenuBar* bar, QWidget* parent);

} // namespace CutCell::ui
