#include "ui/help_menu.h"

#include "ui/help_texts.h"
#include "ui/language.h"
#include "ui/panels/control_panel.h"

#include <QActionGroup>
#include <QCoreApplication>
#include <QDialog>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>

namespace CutCell::ui {

void addLanguageMenu(QMenuBar* bar, QWidget* parent, std::function<void(const QString&)> choose) {
    auto* menu = bar->addMenu(QCoreApplication::translate("HelpMenu", "&Language"));
    menu->setObjectName("languageMenu");
    auto* group = new QActionGroup(menu);
    const QString remembered = rememberedLanguage();
    for (const GuiLanguage& l : guiLanguages()) {
        QAction* a = menu->addAction(l.nativeName);
        a->setObjectName(QStringLiteral("language_%1").arg(l.code));
        a->setCheckable(true);
        a->setChecked(l.code == remembered);
        a->setActionGroup(group);
        QObject::connect(a, &QAction::triggered, parent, [choose, code = l.code] { choose(code); });
    }
}

void addHelpMenu(QMenuBar* bar, QWidget* parent) {
    auto* help = bar->addMenu(QCoreApplication::translate("HelpMenu", "&Help"));
    help->setObjectName("helpMenu");
    help->addAction(QCoreApplication::translate("HelpMenu", "&Keys"), parent, [parent] {
        QMessageBox::information(parent, QCoreApplication::translate("HelpMenu", "Keys"),
                                 ControlPanel::keysHelp());
    });
    QAction* manual = help->addAction(QCoreApplication::translate("HelpMenu", "&Manual"), parent,
                                      [parent] { makeManualWindow(parent)->show(); });
    manual->setObjectName("actionManual");
    QAction* about = help->addAction(
        QCoreApplication::translate("HelpMenu", "&About CutCell"), parent, [parent] {
            QMessageBox::about(parent, QCoreApplication::translate("HelpMenu", "About CutCell"),
                               aboutText());
        });
    about->setObjectName("actionAbout");
}

} // namespace CutCell::ui
