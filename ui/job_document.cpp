#include "ui/job_document.h"

#include "core/job/job_io.h"
#include "core/json/json.h"

#include <QFileInfo>
#include <QSettings>

namespace CutCell::ui {

namespace {
constexpr const char* kRecentKey = "jobs/recent";
}

JobDocument::JobDocument(JobEditor* editor, QObject* parent) : QObject(parent), editor_(editor) {
    connect(editor_, &JobEditor::edited, this, [this] { setModified(true); });
}

QString JobDocument::displayName() const {
    const QString name = QString::fromStdString(editor_->job().name);
    const QString file = path_.isEmpty() ? tr("untitled") : QFileInfo(path_).fileName();
    return name.isEmpty() ? file : QStringLiteral("%1 - %2").arg(name, file);
}

bool JobDocument::newJob(const cutcell::Job& job, QString* why) {
    if (const QString refused = editor_->openLockReason(job); !refused.isEmpty()) {
        if (why) *why = refused;
        return false;
    }
    editor_->setJob(job);
    path_.clear();
    modified_ = false;
    emit changed();
    return true;
}

void JobDocument::adopt(const cutcell::Job& job, const QString& path, bool modified) {
    editor_->setJob(job);
    path_ = path;
    modified_ = modified;
    emit changed();
}

bool JobDocument::open(const QString& path, QString* error) {
    try {
        const std::string text = cutcell::readTextFile(path.toStdString());
        cutcell::json::Value doc;
        try {
            doc = cutcell::json::parse(text);
        } catch (const cutcell::json::ParseError& e) {
            throw cutcell::JobError(std::string("not valid JSON: ") + e.what());
        }
        // Range problems are not refused here: the forms mark them and Start stays disabled.
        const cutcell::Job job = cutcell::jobFromJson(doc);
        // User levels: a file that changes machine parameters needs their level.
        if (const QString why = editor_->openLockReason(job); !why.isEmpty())
            throw cutcell::JobError(why.toStdString());
        editor_->setJob(job);
    } catch (const std::exception& e) {
        if (error) *error = tr("Cannot open %1: %2").arg(path, QString::fromUtf8(e.what()));
        return false;
    }
    path_ = QFileInfo(path).absoluteFilePath();
    modified_ = false;
    addRecent(path_);
    emit changed();
    return true;
}

bool JobDocument::save(QString* error) {
    if (path_.isEmpty()) {
        if (error) *error = tr("The job has no file yet: use Save As.");
        return false;
    }
    return saveAs(path_, error);
}

bool JobDocument::saveAs(const QString& path, QString* error) {
    try {
        cutcell::saveJobFile(editor_->job(), path.toStdString());
    } catch (const std::exception& e) {
        if (error) *error = tr("Cannot save %1: %2").arg(path, QString::fromUtf8(e.what()));
        return false;
    }
    path_ = QFileInfo(path).absoluteFilePath();
    modified_ = false;
    addRecent(path_);
    emit changed();
    return true;
}

QStringList JobDocument::recentFiles() const {
    return QSettings().value(kRecentKey).toStringList();
}

void JobDocument::clearRecentFiles() {
    QSettings().remove(kRecentKey);
    emit recentFilesChanged();
}

void JobDocument::setModified(bool m) {
    if (modified_ == m) return;
    modified_ = m;
    emit changed();
}

void JobDocument::addRecent(const QString& path) {
    QStringList list = recentFiles();
    list.removeAll(path);
    list.prepend(path);
    while (list.size() > kMaxRecent)
        list.removeLast();
    QSettings().setValue(kRecentKey, list);
    emit recentFilesChanged();
}

} // namespace CutCell::ui
