#include "ui/help_texts.h"

#include "ui/build_info.h"
#include "ui/language.h"
#include "ui/machine/machine_ui_registry.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFile>
#include <QGuiApplication>
#include <QPushButton>
#include <QScreen>
#include <QStringList>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <QtGlobal>

namespace CutCell::ui {
namespace {

// "## Title" -> level 2 and "Title"; 0 for a line that is no heading. A line inside a fenced
// or indented code block is never a heading (the caller skips those).
int headingLevel(const QString& line, QString* title) {
    int level = 0;
    while (level < line.size() && line[level] == QLatin1Char('#'))
        ++level;
    if (level == 0 || level > 6 || level >= line.size() || line[level] != QLatin1Char(' '))
        return 0;
    *title = line.mid(level + 1).trimmed();
    return level;
}

} // namespace

QString aboutText() {
    QStringList machines;
    for (const MachineUi* m : machineUis())
        machines << m->title().toHtmlEscaped();
    return QCoreApplication::translate(
               "HelpTexts",
               "<h3>CutCell operator station %1</h3>"
               "<p>Build: %2 (%3), %4, %5<br>Qt %6 (built with %7)<br>Language: %8</p>"
               "<p>Machines in this build:</p><ul><li>%9</li></ul>"
               "<p>The manual (Help &rarr; Manual) is the README's operator sections of this "
               "build.</p>")
        .arg(QCoreApplication::applicationVersion().toHtmlEscaped(),
             QString::fromUtf8(buildCommit()).toHtmlEscaped(),
             QString::fromUtf8(buildCommitDate()).toHtmlEscaped(),
             QString::fromUtf8(buildType()).toHtmlEscaped(),
             QString::fromUtf8(buildCompiler()).toHtmlEscaped(), QString::fromUtf8(qVersion()),
             QStringLiteral(QT_VERSION_STR), shownLanguage(),
             machines.join(QStringLiteral("</li><li>")));
}

QString operatorManual(const QString& readmeMarkdown) {
    const QStringList lines = readmeMarkdown.split(QLatin1Char('\n'));
    QStringList out;
    bool taking = false;
    int takenLevel = 0;
    QString machineHeading; // the level-2 heading above an "### In the GUI"
    bool inFence = false;
    for (const QString& line : lines) {
        if (line.trimmed().startsWith(QLatin1String("```"))) inFence = !inFence;
        QString title;
        const int level = inFence ? 0 : headingLevel(line, &title);
        if (level > 0 && level <= 3) {
            if (taking && level <= takenLevel) taking = false;
            if (level == 2) machineHeading = title;
            if (level == 2 && title.startsWith(QLatin1String("The operator station"))) {
                taking = true;
                takenLevel = 2;
            } else if (level == 3 && title == QLatin1String("In the GUI")) {
                out << QStringLiteral("## %1: %2").arg(machineHeading, title) << QString();
                taking = true;
                takenLevel = 3;
                continue;
            }
        }
        if (taking) out << line;
    }
    return out.join(QLatin1Char('\n')).trimmed();
}

QString builtInManual() {
    if (shownLanguage() == QLatin1String("de")) {
        // The translation starts with a comment naming the English text it translates.
        QFile de(QStringLiteral(":/cutcell/manual/manual_de.md"));
        if (de.open(QIODevice::ReadOnly)) {
            QString text = QString::fromUtf8(de.readAll());
            if (text.startsWith(QLatin1String("<!--")))
                text = text.mid(text.indexOf(QLatin1String("-->")) + 3);
            return text.trimmed();
        }
    }
    QFile f(QStringLiteral(":/cutcell/manual/README.md"));
    if (!f.open(QIODevice::ReadOnly)) return {};
    return operatorManual(QString::fromUtf8(f.readAll()));
}

QString manualImageRoot() {
    return QStringLiteral(":/cutcell/manual");
}

QDialog* makeManualWindow(QWidget* parent) {
    auto* dialog = new QDialog(parent);
    dialog->setObjectName("manualWindow");
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(
        QCoreApplication::translate("HelpTexts", "CutCell manual: the operator station"));
    auto* layout = new QVBoxLayout(dialog);
    auto* text = new QTextBrowser(dialog);
    text->setObjectName("manualText");
    text->setOpenExternalLinks(false);
    text->setSearchPaths({manualImageRoot()});
    const QString manual = builtInManual();
    if (manual.isEmpty())
        text->setPlainText(QCoreApplication::translate(
            "HelpTexts", "The manual is missing from this build (README.md)."));
    else
        text->setMarkdown(manual);
    layout->addWidget(text);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    layout->addWidget(buttons);
    // Within the screen: at most 90 % of its available area.
    QSize size(900, 700);
    if (const QScreen* s = parent ? parent->screen() : QGuiApplication::primaryScreen())
        size = size.boundedTo(s->availableGeometry().size() * 0.9);
    dialog->resize(size);
    return dialog;
}

} // namespace CutCell::ui
