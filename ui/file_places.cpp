#include "ui/file_places.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>

namespace CutCell::ui {

namespace {

SavePathPrompt& prompt() {
    static SavePathPrompt p;
    return p;
}

const char* settingsKey(SaveKind kind) {
    return kind == SaveKind::Job ? "files/jobs_dir" : "files/exports_dir";
}

QString folder(SaveKind kind, const char* leaf) {
    const QString remembered = QSettings().value(QLatin1String(settingsKey(kind))).toString();
    if (!remembered.isEmpty() && QFileInfo(remembered).isDir()) return remembered;
    return QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
        .filePath(QStringLiteral("CutCell/") + QLatin1String(leaf));
}

bool isShipped(const QString& path) {
    if (path.startsWith(QLatin1String(":/"))) return true; // compiled into the program
#ifdef CUTCELL_SHIPPED_JOBS_DIR
    const QString shipped = QDir(QStringLiteral(CUTCELL_SHIPPED_JOBS_DIR)).canonicalPath();
    const QString file = QFileInfo(path).canonicalFilePath();
    return !shipped.isEmpty() && !file.isEmpty() && file.startsWith(shipped + QLatin1Char('/'));
#else
    (void)path;
    return false;
#endif
}

} // namespace

bool mustNotOverwrite(const QString& path) {
    if (path.isEmpty()) return false;
    if (isShipped(path)) return true;
    const QFileInfo f(path);
    return f.exists() && !f.isWritable();
}

QString jobsFolder() {
    return folder(SaveKind::Job, "jobs");
}

QString exportsFolder() {
    return folder(SaveKind::Export, "exports");
}

QString fileStem(const QString& documentPath, const QString& jobName) {
    QString stem = documentPath.isEmpty() ? QString() : QFileInfo(documentPath).completeBaseName();
    if (stem.isEmpty()) stem = jobName.trimmed();
    // Letters, digits, '-', '_' and '.' only: a name typed in the form can hold anything.
    stem.replace(QRegularExpression(QStringLiteral("[^\\w.-]+")), QStringLiteral("_"));
    stem.remove(QRegularExpression(QStringLiteral("^[._]+|_+$")));
    return stem.isEmpty() ? QStringLiteral("job") : stem.left(80);
}

QString proposedJobPath(const QString& documentPath, const QString& jobName) {
    QString stem = fileStem(documentPath, jobName);
    if (isShipped(documentPath)) stem += QStringLiteral("_copy");
    return QDir(jobsFolder()).filePath(stem + QStringLiteral(".json"));
}

QString proposedExportPath(const QString& documentPath, const QString& jobName,
                           const QString& tail) {
    return QDir(exportsFolder()).filePath(fileStem(documentPath, jobName) + tail);
}

QString filterSuffix(const QString& filter) {
    const auto m = QRegularExpression(QStringLiteral("\\*(\\.[A-Za-z0-9]+)")).match(filter);
    return m.hasMatch() ? m.captured(1) : QString();
}

void setSavePathPrompt(SavePathPrompt p) {
    prompt() = std::move(p);
}

QString askSavePath(QWidget* parent, SaveKind kind, const QString& title, const QString& proposed,
                    const QString& filter) {
    QDir().mkpath(QFileInfo(proposed).absolutePath()); // the dialog opens in it
    const QString chosen = prompt() ? prompt()(title, proposed, filter)
                                    : QFileDialog::getSaveFileName(parent, title, proposed, filter);
    if (!chosen.isEmpty())
        QSettings().setValue(QLatin1String(settingsKey(kind)), QFileInfo(chosen).absolutePath());
    return chosen;
}

} // namespace CutCell::ui
