// Issue 21: the GUI in German and English (Qt Linguist catalogue, ui/language.h), switched from
// the Language menu without losing the job (ui/window_host.h), and Help -> About / Manual.
#include "sim_rig.h"

#include "main_window_run.h"
#include "ui/build_info.h"
#include "ui/forms/issue_text.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/number_fields.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/help_texts.h"
#include "ui/job_document.h"
#include "ui/language.h"
#include "ui/machine/machine_ui_registry.h"
#include "ui/main_window.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/engine_text.h"
#include "ui/panels/event_log_panel.h"
#include "ui/window_host.h"

#include <cerrno>

#include "core/common/c_format.h"
#include "core/engine/realtime_thread.h"
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QCryptographicHash>
#include <QDialog>
#include <QFile>
#include <QGroupBox>
#include <QHeaderView>
#include <QImage>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTextDocument>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

using CutCell::ui::MainWindow;

namespace CutCell::ui {
// The engine's event templates (resources/i18n/core_messages.cpp, tools/core_messages.py).
extern const char* const kCoreMessages[];
extern const int kCoreMessageCount;
} // namespace CutCell::ui

namespace {

// A template formatted as core formats it (snprintfC, C notation), with sample values: the
// words "Qx" (no template's), the integers 7, the reals 1.25, the hex numbers 0x2310.
QString sampleOf(const char* tmpl) {
    static const QRegularExpression spec(
        QStringLiteral(R"(%[-+ #0]*\d*(?:\.\d+)?(?:ll|l|z|h)?[diuxXfgeEsc%])"));
    const QString t = QString::fromUtf8(tmpl);
    QString out;
    qsizetype last = 0;
    for (auto it = spec.globalMatch(t); it.hasNext();) {
        const auto m = it.next();
        out += t.mid(last, m.capturedStart() - last);
        last = m.capturedEnd();
        const QByteArray one = m.captured().toLatin1();
        char buf[64];
        switch (one.back()) {
        case '%':
            std::snprintf(buf, sizeof buf, "%%");
            break;
        case 's':
            std::snprintf(buf, sizeof buf, "Qx");
            break;
        case 'f':
        case 'g':
        case 'e':
            cutcell::snprintfC(buf, sizeof buf, one.constData(), 1.25);
            break;
        case 'X':
        case 'x':
            std::snprintf(buf, sizeof buf, one.constData(), 0x2310u);
            break;
        default:
            if (one.contains('z'))
                std::snprintf(buf, sizeof buf, one.constData(), size_t{7});
            else if (one.contains('l'))
                std::snprintf(buf, sizeof buf, one.constData(), 7L);
            else
                std::snprintf(buf, sizeof buf, one.constData(), 7);
        }
        out += QString::fromLatin1(buf);
    }
    return out + t.mid(last);
}

// Every text a widget of the window shows or tells (labels, buttons, group titles, tabs,
// table headers, combo items, menus, tooltips), in the order the widgets were made.
QStringList shownTexts(const MainWindow& w) {
    QStringList out;
    auto add = [&out](const QString& t) {
        QTextDocument d;
        d.setHtml(t);
        const QString plain = Qt::mightBeRichText(t) ? d.toPlainText() : t;
        out << plain.simplified();
    };
    for (const QWidget* c : w.findChildren<QWidget*>()) {
        if (auto* l = qobject_cast<const QLabel*>(c)) add(l->text());
        if (auto* b = qobject_cast<const QAbstractButton*>(c)) add(b->text());
        if (auto* g = qobject_cast<const QGroupBox*>(c)) add(g->title());
        if (auto* t = qobject_cast<const QTabWidget*>(c))
            for (int i = 0; i < t->count(); ++i)
                add(t->tabText(i));
        if (auto* t = qobject_cast<const QTableWidget*>(c))
            for (int i = 0; i < t->columnCount(); ++i)
                if (t->horizontalHeaderItem(i)) add(t->horizontalHeaderItem(i)->text());
        if (auto* cb = qobject_cast<const QComboBox*>(c))
            for (int i = 0; i < cb->count(); ++i)
                add(cb->itemText(i));
        add(c->toolTip());
    }
    for (const QMenu* m : w.menuBar()->findChildren<QMenu*>()) {
        add(m->title());
        for (const QAction* a : m->actions())
            add(a->text());
    }
    return out;
}

// A text the same in both languages that is a sentence or a label an operator reads: a word of
// four or more letters that is none of the names both languages share.
bool readsAsEnglish(const QString& text) {
    static const QStringList shared = {
        // units, formats, buses and names that German keeps (the seeds' angle names too)
        "deg", "rpm", "JSON", "CSV", "PNG", "SVG", "PDF", "G-code", "DSTV", "CANopen", "SocketCAN",
        "virtualcan", "Override", "Start", "Reset", "Jacobian", "Whitworth", "English", "Deutsch",
        "System", "Experiment", "CutCell", "Pitch", "Status", "Name", "Info", "Heartbeat", "Alarm",
        "Pause", "json", "alpha", "beta", "Offset", "Amplitude", "kbit", "SYNC", "inverse", "RPDO",
        "TPDO", "eventfd", "EMCY",
        // cutting processes German names alike
        "Plasma", "Laser",
        // limits.conf's keyword (the real-time line's advice names it)
        "rtprio",
        // CiA 301 NMT states, named so in German manuals too
        "Operational", "Boot"};
    // Identifiers from a data file (a cut chart's material "mild_steel") are shown as written.
    static const QRegularExpression identifier(QStringLiteral("^[a-z0-9]+(_[a-z0-9]+)+$"));
    if (identifier.match(text).hasMatch()) return false;
    // The machines' axis names are names ("chuck (theta0)", "groove θ2"), as in the papers.
    if (text.contains(QStringLiteral("theta")) || text.contains(QChar(0x03B8))) return false;
    static const QRegularExpression word(QStringLiteral("[A-Za-z]{4,}"));
    for (auto it = word.globalMatch(text); it.hasNext();) {
        const QString m = it.next().captured();
        if (!shared.contains(m)) return true;
    }
    return false;
}

// The words of an English text (four letters or more, not shared by both languages) that its
// German text still has.
QStringList englishWordsKept(const QString& english, const QString& german) {
    static const QRegularExpression word(QStringLiteral("[A-Za-z_]{4,}"));
    // The job's keys the validation sentences name (both languages keep them: the form
    // replaces them by the field's label): dotted or indexed keys, quoted values, and the
    // section a sentence starts with ("mechanism: ...").
    // (A plain literal: moc's lexer loses its way in a raw string with quotes inside.)
    static const QRegularExpression key(
        QStringLiteral("[A-Za-z_][A-Za-z_0-9]*(?:\\[[^\\]]*\\])*(?:\\.[A-Za-z_0-9]+"
                       "(?:\\[[^\\]]*\\])*)+|\"[^\"]*\"|^[a-z_]+:"));
    const QString text = QString(english).replace(key, QStringLiteral(" "));
    const QString translated = QString(german).replace(key, QStringLiteral(" "));
    QStringList kept;
    for (auto it = word.globalMatch(text); it.hasNext();) {
        const QString w = it.next().captured();
        if (readsAsEnglish(w) && !w.contains('_') &&
            translated.contains(QRegularExpression("\\b" + w + "\\b")) && !kept.contains(w))
            kept << w;
    }
    return kept;
}

} // namespace

class TestGuiLanguage : public QObject {
    Q_OBJECT

    QTemporaryDir dir_;

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().remove("ui/language");
        QSettings().remove("jobs/recent"); // files other runs opened are no texts of the window
        QVERIFY(dir_.isValid());
    }
    void cleanup() { QVERIFY(CutCell::ui::applyGuiLanguage("en")); }

    // The German catalogue is in the binary and reaches the window's texts and numbers.
    void germanWindowSpeaksGerman() {
        QVERIFY(CutCell::ui::applyGuiLanguage("de"));
        QCOMPARE(CutCell::ui::shownLanguage(), QStringLiteral("de"));
        MainWindow w(&cutcell::app::makeRig);
        QVERIFY2(w.controls()->eStopButton()->text().startsWith("NOT-HALT"),
                 qPrintable(w.controls()->eStopButton()->text()));
        QCOMPARE(w.menuBar()->actions().front()->text(), QStringLiteral("&Datei"));
        QCOMPARE(QLocale().decimalPoint(), QStringLiteral(","));
        auto* speed = qobject_cast<QAbstractSpinBox*>(w.parameters()->fieldFor("cut.speed_mm_s"));
        QVERIFY(speed);
        QVERIFY2(speed->text().contains(','), qPrintable(speed->text()));
        // Qt's own texts follow (qt6-translations-l10n): the dialogs' buttons.
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"),
                 QStringLiteral("Abbrechen"));
    }

    // A language the build has no catalogue for is refused with its name; English stays.
    void unknownLanguageIsRefused() {
        QString why;
        QVERIFY(!CutCell::ui::applyGuiLanguage("fr", &why));
        QVERIFY2(why.contains("fr") && why.contains("de"), qPrintable(why));
        QCOMPARE(CutCell::ui::shownLanguage(), QStringLiteral("en"));
    }

    // The Language menu rebuilds the window in German with the job as it was: the file, the
    // unsaved edit, the modified mark and the tab; the choice is remembered.
    void switchingKeepsTheJob() {
        const QString path = dir_.filePath("job.json");
        cutcell::saveJobFile(cutcell::defaultJob(), path.toStdString());
        CutCell::ui::WindowHost host(&cutcell::app::makeRig);
        MainWindow* before = host.window();
        QString error;
        QVERIFY2(before->openJob(path, &error), qPrintable(error));
        before->editor()->edit([](cutcell::Job& j) {
            j.cut.speed_mm_s = 33.5;
            j.description = "edited, not saved";
        });
        before->parameters()->tabs()->setCurrentIndex(2);
        QVERIFY(before->document()->modified());
        before->show();

        QString why;
        QVERIFY2(host.changeLanguage("de", &why), qPrintable(why));
        MainWindow* after = host.window();
        QVERIFY(after != before);
        QVERIFY(after->isVisible());
        QVERIFY2(after->controls()->eStopButton()->text().startsWith("NOT-HALT"),
                 qPrintable(after->controls()->eStopButton()->text()));
        QCOMPARE(after->editor()->job().cut.speed_mm_s, 33.5);
        QCOMPARE(after->editor()->job().description, std::string("edited, not saved"));
        QVERIFY(after->document()->modified());
        QCOMPARE(after->document()->path(), QFileInfo(path).absoluteFilePath());
        QCOMPARE(after->parameters()->tabs()->currentIndex(), 2);
        auto* speed =
            qobject_cast<QAbstractSpinBox*>(after->parameters()->fieldFor("cut.speed_mm_s"));
        QVERIFY2(speed->text().startsWith("33,5"), qPrintable(speed->text()));
        QCOMPARE(QSettings().value("ui/language").toString(), QStringLiteral("de"));
        // The file on disk is untouched (C notation, the saved values).
        QCOMPARE(cutcell::loadJobFile(path.toStdString()).cut.speed_mm_s,
                 cutcell::defaultJob().cut.speed_mm_s);

        QVERIFY2(host.changeLanguage("en", &why), qPrintable(why));
        QVERIFY2(host.window()->controls()->eStopButton()->text().startsWith("EMERGENCY"),
                 qPrintable(host.window()->controls()->eStopButton()->text()));
        QCOMPARE(host.window()->editor()->job().cut.speed_mm_s, 33.5);
        QSettings().remove("ui/language");
    }

    // While the machine moves the window stays as it is (no rebuild under a running cut),
    // and the log says why.
    void noSwitchWhileTheMachineMoves() {
        QTemporaryDir runs;
        CutCell::ui::WindowHost host(&cutcell::app::makeRig);
        MainWindow* w = host.window();
        auto job = cutcell::defaultJob();
        job.sim.duration_s = 6;
        job.engine.runs_dir = runs.path().toStdString();
        w->editor()->setJob(job);
        w->show();
        startManually(*w);
        QTRY_VERIFY2_WITH_TIMEOUT(state(*w) == cutcell::EngineState::Running,
                                  cutcell::toString(state(*w)), 10000);
        QString why;
        QVERIFY(!host.changeLanguage("de", &why));
        QVERIFY2(why.contains("moving"), qPrintable(why));
        QCOMPARE(host.window(), w);
        QVERIFY2(lastLog(*w).contains("The language was not changed"), qPrintable(lastLog(*w)));
        QVERIFY(w->controls()->eStopButton()->text().startsWith("EMERGENCY"));
        w->run()->emergencyStop();
        QTRY_VERIFY2_WITH_TIMEOUT(state(*w) == cutcell::EngineState::EmergencyStop,
                                  cutcell::toString(state(*w)), 5000);
        QVERIFY(!host.changeLanguage("de", &why));
        QVERIFY2(why.contains("first"), qPrintable(why));
    }

    // Each text the German window shows that reads as English in both windows is a text
    // without tr() or with a context the catalogue does not know: none may be left.
    void everyShownTextIsTranslated() {
        QVERIFY(CutCell::ui::applyGuiLanguage("en"));
        MainWindow english(nullptr);
        const QStringList en = shownTexts(english);
        QVERIFY(CutCell::ui::applyGuiLanguage("de"));
        MainWindow german(nullptr);
        const QStringList de = shownTexts(german);
        QCOMPARE(de.size(), en.size());
        QStringList untranslated;
        for (int i = 0; i < en.size(); ++i)
            if (!en[i].isEmpty() && en[i] == de[i] && readsAsEnglish(en[i]) &&
                !untranslated.contains(en[i]))
                untranslated << en[i];
        for (const QString& t : untranslated)
            qWarning("the same in German: %s", qPrintable(t));
        QVERIFY2(untranslated.isEmpty(), qPrintable(QString("%1 texts the same in German:\n%2")
                                                        .arg(untranslated.size())
                                                        .arg(untranslated.join("\n"))));
        QVERIFY(en.size() > 300); // the window was walked, not an empty one
    }

    // The engine's events (core writes them in English) in German: each template is found
    // again from a text formatted from it, reads the same in English, and in German has no
    // English word left and its numbers with the decimal comma.
    void everyEngineTextReadsInGerman() {
        QVERIFY(CutCell::ui::kCoreMessageCount > 150);
        QStringList problems;
        for (int i = 0; i < CutCell::ui::kCoreMessageCount; ++i) {
            const char* tmpl = CutCell::ui::kCoreMessages[i];
            const QString sample = sampleOf(tmpl);
            QVERIFY(CutCell::ui::applyGuiLanguage("en"));
            const char* found = CutCell::ui::engineTemplateOf(sample);
            if (!found || std::strcmp(found, tmpl) != 0)
                problems << QString("\"%1\" was taken for \"%2\"")
                                .arg(sample, found ? QString::fromUtf8(found) : "nothing");
            if (CutCell::ui::engineText(sample) != sample)
                problems << QString("changed in English: \"%1\" -> \"%2\"")
                                .arg(sample, CutCell::ui::engineText(sample));
            QVERIFY(CutCell::ui::applyGuiLanguage("de"));
            const QString german = CutCell::ui::engineText(sample);
            if (!englishWordsKept(sample, german).isEmpty())
                problems << QString("English in German: \"%1\" -> \"%2\" (%3)")
                                .arg(sample, german, englishWordsKept(sample, german).join(' '));
            if (sample.contains("1.25") && !german.contains("1,25"))
                problems << QString("no decimal comma: \"%1\" -> \"%2\"").arg(sample, german);
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join("\n")));
    }

    // Texts nested in one another (a refusal's reason, the tool, a state) are translated each.
    void nestedEngineTextsAreTranslatedEach() {
        QVERIFY(CutCell::ui::applyGuiLanguage("de"));
        QCOMPARE(CutCell::ui::engineText("Start refused: not homed (Home first)"),
                 QStringLiteral("Start abgelehnt: nicht referenziert (zuerst Referenz)"));
        QCOMPARE(CutCell::ui::engineText("Paused on the path at 2.500 s (saw off)"),
                 QStringLiteral("Auf der Bahn angehalten bei 2,500 s (Säge aus)"));
        QCOMPARE(CutCell::ui::engineText("Home refused: motion in progress (Paused)"),
                 QStringLiteral("Referenz abgelehnt: Bewegung läuft (Vorschub halt)"));
        // The CAN master's: the node's prefix and its fault each; a list item by item.
        QCOMPARE(CutCell::ui::engineText("node 3: heartbeat lost (none for 250 ms > 200 ms)"),
                 QStringLiteral("Knoten 3: Heartbeat verloren (keiner seit 250 ms > 200 ms)"));
        QCOMPARE(CutCell::ui::engineText("CAN bus: bus off (bus off, transmit timeout)"),
                 QStringLiteral("CAN-Bus: Bus aus (Bus aus (Bus-Off), Sendezeitüberschreitung)"));
        // A text no template knows (a device's own message) is shown as it came.
        QCOMPARE(CutCell::ui::engineText("vendor code E-42 (see the drive's manual)"),
                 QStringLiteral("vendor code E-42 (see the drive's manual)"));
    }

    // The engine thread's real-time line (the first event of a paced run), as core writes it:
    // its items joined by "; ", each translated.
    void realtimeLineReadsInGerman() {
        QVERIFY(CutCell::ui::applyGuiLanguage("de"));
        cutcell::RealtimeSettings asked;
        asked.priority = 80;
        asked.lock_memory = true;
        asked.cpu = 1;
        asked.cpu_dma_latency = true;
        cutcell::RealtimeStatus granted;
        granted.rt_priority_granted = true;
        granted.priority = 80;
        granted.memory_locked = true;
        granted.cpu_pinned = true;
        granted.dma_latency_held = true;
        char line[640]; // as the engine's thread (it emits the line in 239-character events)
        QVERIFY(cutcell::describeRealtime(asked, granted, line, sizeof line));
        QCOMPARE(CutCell::ui::engineText(QString::fromUtf8(line)),
                 QStringLiteral("Echtzeit: SCHED_FIFO 80 gewährt; Speicher gesperrt; an CPU 1 "
                                "gebunden; /dev/cpu_dma_latency auf 0 µs gehalten"));
        cutcell::RealtimeStatus refused;
        refused.priority_error = EPERM;
        refused.lock_error = EAGAIN;
        refused.cpu_error = EINVAL;
        refused.dma_latency_error = EACCES;
        QVERIFY(!cutcell::describeRealtime(asked, refused, line, sizeof line));
        const QString german = CutCell::ui::engineText(QString::fromUtf8(line));
        for (const char* english : {"Real-time", "granted", "needs", "memory", "pinned", "held"})
            QVERIFY2(!german.contains(QLatin1String(english)), qPrintable(german));
        for (const char* word : {"SCHED_FIFO 80 nicht gewährt", "Speicher nicht gesperrt",
                                 "nicht an CPU 1 gebunden", "/dev/cpu_dma_latency nicht gehalten"})
            QVERIFY2(german.contains(QString::fromUtf8(word)), qPrintable(german));
    }

    // A cross-field check of the job's validation (no range: a sentence of core) in German,
    // the field named by its label, the numbers with the decimal comma.
    void validationSentenceReadsInGerman() {
        auto job = cutcell::defaultJob();
        job.eccentricity_mm = 0;
        job.main_pipe.radius_mm = 60;
        job.branch_pipe.radius_mm = 70.5;
        const auto issues = cutcell::validateJob(job);
        const auto it = std::find_if(issues.begin(), issues.end(), [](const auto& i) {
            return i.key == "branch_pipe.radius_mm" && !std::isfinite(i.lo);
        });
        QVERIFY2(it != issues.end(), "no fit issue for branch_pipe.radius_mm");
        QVERIFY(CutCell::ui::applyGuiLanguage("de"));
        const QString text = CutCell::ui::issueText(*it, QStringLiteral("Abzweigradius"));
        QVERIFY2(text.startsWith(QStringLiteral("Abzweigradius = 70,5 mm passt nicht")),
                 qPrintable(text));
        QVERIFY2(!englishWordsKept(QString::fromStdString(it->message), text).size(),
                 qPrintable(text));
        QVERIFY(CutCell::ui::applyGuiLanguage("en"));
        QVERIFY2(CutCell::ui::issueText(*it, QStringLiteral("Branch radius"))
                     .startsWith(QStringLiteral("Branch radius = 70.5 mm does not fit")),
                 qPrintable(CutCell::ui::issueText(*it, QStringLiteral("Branch radius"))));
    }

    // A planner's refusal on a shipped job made infeasible (the flying saw's carriage slower
    // than the line), as the GUI shows it: German, numbers with the decimal comma.
    void plannerRefusalReadsInGerman() {
        QFile file(QStringLiteral(CUTCELL_SOURCE_DIR "/resources/jobs/flying_saw_job.json"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        std::string text = file.readAll().toStdString();
        const std::string fast = "\"max_speed_mm_s\": 3000";
        QVERIFY(text.find(fast) != std::string::npos);
        text.replace(text.find(fast), fast.size(), "\"max_speed_mm_s\": 900.5");
        const cutcell::Job job = cutcell::parseJob(text);
        const cutcell::MachineModule* module = cutcell::findMachine(job.machine);
        QVERIFY(module);
        const cutcell::MachinePlan plan = module->plan(job, text);
        QVERIFY(!plan.ok());
        const QString english = QString::fromStdString(plan.outcome.message);
        QVERIFY2(english.contains("cannot reach the line"), qPrintable(english));
        QVERIFY(CutCell::ui::applyGuiLanguage("de"));
        const QString german = CutCell::ui::engineText(english);
        QVERIFY2(
            german.startsWith(QStringLiteral("nicht ausführbar: machine.carriage.max_speed_mm_s "
                                             "= 900,5 mm/s erreicht die Linie nicht")),
            qPrintable(german));
        QVERIFY2(englishWordsKept(english, german).isEmpty(), qPrintable(german));

        // The window names the key by the field's label, in the Start reason and in the log.
        QTemporaryDir dir;
        const QString path = dir.filePath("slow_carriage.json");
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(text.c_str());
        out.close();
        MainWindow w(nullptr);
        QString error;
        QVERIFY2(w.openJob(path, &error), qPrintable(error));
        const QWidget* field = w.parameters()->fieldFor("carriage.max_speed_mm_s");
        QVERIFY(field && !field->accessibleName().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->startBlockedReason().contains("Linie"), 20000);
        const QString reason = w.run()->startBlockedReason();
        QVERIFY2(reason.contains(field->accessibleName() + QStringLiteral(" = 900,5 mm/s")),
                 qPrintable(reason));
        QVERIFY2(!reason.contains("max_speed_mm_s"), qPrintable(reason));
        w.document()->clearRecentFiles();
    }

    // Help -> About names the version, the build's commit and every machine.
    void aboutNamesTheBuildAndTheMachines() {
        const QString about = CutCell::ui::aboutText();
        QVERIFY2(about.contains(QString::fromUtf8(CutCell::ui::buildCommit())), qPrintable(about));
        QVERIFY(QString::fromUtf8(CutCell::ui::buildCommit()) != "");
        QVERIFY2(about.contains(QString::fromUtf8(qVersion())), qPrintable(about));
        for (const auto* m : CutCell::ui::machineUis())
            QVERIFY2(about.contains(m->title().toHtmlEscaped()), qPrintable(m->title()));
    }

    // Help -> Manual in German is docs/manual_de.md, the translation of this build's English
    // manual: its first line names the sha256 of the English it translates (an English change
    // without the German fails here), it has the same headings, pictures and command lines in
    // the same order, no English paragraph left as it was, and the German window shows it.
    void germanManualTranslatesThisBuildsManual() {
        QVERIFY(CutCell::ui::applyGuiLanguage("en"));
        const QString english = CutCell::ui::builtInManual();
        const QString hash = QString::fromLatin1(
            QCryptographicHash::hash(english.toUtf8(), QCryptographicHash::Sha256).toHex());
        QFile file(QStringLiteral(CUTCELL_SOURCE_DIR "/docs/manual_de.md"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString german = QString::fromUtf8(file.readAll());
        QVERIFY2(german.section('\n', 0, 0).contains("sha256 " + hash),
                 qPrintable("docs/manual_de.md translates another English manual: translate what "
                            "changed in the README's operator sections, then write sha256 " +
                            hash + " into its first line"));
        const auto lines = [](const QString& text, const QRegularExpression& kind) {
            QStringList out;
            for (const QString& line : text.split('\n'))
                if (const auto m = kind.match(line); m.hasMatch()) out << m.captured(1);
            return out;
        };
        const QRegularExpression heading(QStringLiteral("^(#+) "));
        const QRegularExpression image(QStringLiteral("!\\[[^\\]]*\\]\\(([^)]+)\\)"));
        const QRegularExpression command(QStringLiteral("^(    \\S.*)$"));
        QCOMPARE(lines(german, heading), lines(english, heading));
        QCOMPARE(lines(german, image), lines(english, image));
        QCOMPARE(lines(german, command), lines(english, command));
        for (const QString& para : english.split("\n\n")) {
            const QString p = para.trimmed();
            const bool code = QString(para).remove(QRegularExpression("^\\n+")).startsWith("    ");
            if (p.size() < 60 || code || p.startsWith('|') || p.startsWith("![")) continue;
            QVERIFY2(!german.contains(p), qPrintable("untranslated: " + p.left(80)));
        }
        QVERIFY(CutCell::ui::applyGuiLanguage("de"));
        const QString shown = CutCell::ui::builtInManual();
        QVERIFY2(shown.startsWith("## Der Bedienplatz"), qPrintable(shown.left(80)));
        QVERIFY(!shown.contains("<!--"));
        MainWindow w(nullptr);
        QDialog* window = CutCell::ui::makeManualWindow(&w);
        auto* text = window->findChild<QTextBrowser*>("manualText");
        QVERIFY(text);
        QVERIFY2(text->toPlainText().contains("NOT-HALT"),
                 qPrintable(text->toPlainText().left(200)));
        delete window;
    }

    // Help -> Manual is the README's operator section of this build, offline: its pictures
    // come from the binary, the developers' sections stay out.
    void manualIsTheReadmesOperatorSection() {
        const QString manual = CutCell::ui::builtInManual();
        QFile readme(QStringLiteral(CUTCELL_SOURCE_DIR "/README.md"));
        QVERIFY(readme.open(QIODevice::ReadOnly));
        const QString source = QString::fromUtf8(readme.readAll());
        // Every paragraph of the README's operator section is in the manual, word for word.
        const qsizetype from = source.indexOf("\n## The operator station");
        const qsizetype to = source.indexOf("\n## ", from + 5);
        QVERIFY(from > 0 && to > from);
        for (const QString& para : source.mid(from, to - from).split("\n\n"))
            QVERIFY2(manual.contains(para.trimmed()), qPrintable(para.left(80)));
        QVERIFY(manual.contains("## Flying saw"));         // a machine's "In the GUI"
        QVERIFY(!manual.contains("## The motion engine")); // the developers' sections stay
        QVERIFY(!manual.contains("## Set-up"));
        static const QRegularExpression image(QStringLiteral("!\\[[^\\]]*\\]\\(([^)]+)\\)"));
        int images = 0;
        for (auto it = image.globalMatch(manual); it.hasNext(); ++images) {
            const QString file = CutCell::ui::manualImageRoot() + "/" + it.next().captured(1);
            QVERIFY2(!QImage(file).isNull(), qPrintable(file + " is not in the binary"));
        }
        QVERIFY(images >= 3);
        // The window shows it.
        MainWindow w(nullptr);
        QDialog* window = CutCell::ui::makeManualWindow(&w);
        window->show();
        auto* text = window->findChild<QTextBrowser*>("manualText");
        QVERIFY(text);
        QVERIFY(text->toPlainText().contains("EMERGENCY STOP"));
        window->close();
    }

    // No menu takes F1: it is the EMERGENCY STOP's (Help's usual key included).
    void noMenuTakesF1() {
        MainWindow w(nullptr);
        for (const QAction* a : w.menuBar()->findChildren<QAction*>())
            QVERIFY2(a->shortcut() != QKeySequence(Qt::Key_F1), qPrintable(a->text()));
        QVERIFY(w.menuBar()->findChild<QMenu*>("languageMenu"));
        QVERIFY(w.menuBar()->findChild<QMenu*>("helpMenu"));
    }
};

QTEST_MAIN(TestGuiLanguage)
#include "test_gui_language.moc"
