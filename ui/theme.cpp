#include "ui/theme.h"

#include <QApplication>
#include <QFile>
#include <QPalette>
#include <QStyleFactory>

static void initUiResources() {
    Q_INIT_RESOURCE(ui_resources);
}

namespace CutCell::ui {

QString darkIndustrialStyleSheet() {
    initUiResources();
    QFile f(QStringLiteral(":/cutcell/style/dark_industrial.qss"));
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) return {};
    return QString::fromUtf8(f.readAll());
}

bool applyDarkIndustrialTheme(QApplication& app) {
    const QString qss = darkIndustrialStyleSheet();
    if (qss.isEmpty()) return false;
    app.setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QPalette p;
    p.setColor(QPalette::Window, QColor(0x1d, 0x21, 0x26));
    p.setColor(QPalette::WindowText, QColor(0xe4, 0xe8, 0xec));
    p.setColor(QPalette::Base, QColor(0x12, 0x15, 0x1a));
    p.setColor(QPalette::AlternateBase, QColor(0x1a, 0x1e, 0x23));
    p.setColor(QPalette::Text, QColor(0xe4, 0xe8, 0xec));
    p.setColor(QPalette::Button, QColor(0x2d, 0x34, 0x3c));
    p.setColor(QPalette::ButtonText, QColor(0xe4, 0xe8, 0xec));
    p.setColor(QPalette::Highlight, QColor(0x2f, 0x6f, 0xb0));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::ToolTipBase, QColor(0x2b, 0x31, 0x39));
    p.setColor(QPalette::ToolTipText, QColor(0xf0, 0xf3, 0xf6));
    app.setPalette(p);
    app.setStyleSheet(qss);
    return true;
}

} // namespace CutCell::ui
