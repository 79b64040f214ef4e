#pragma once
// The job as a document: its file, its modified flag and the recent-files list. Files are read
// with core jobFromJson (an invalid job still opens, with its fields marked) and written with
// core saveJobFile (atomic: temporary file + rename).
//
// Threading contract: GUI thread only.
#include "ui/forms/job_editor.h"

#include <QObject>
#include <QString>
#include <QStringList>

namespace CutCell::ui {

class JobDocument : public QObject {
    Q_OBJECT
  public:
    JobDocument(JobEditor* editor, QObject* parent = nullptr);

    QString path() const { return path_; }
    bool modified() const { return modified_; }
    // "name - file.json" for the window title (Qt's [*] marks modified).
    QString displayName() const;

    // False, with the reason, when the editor's open gate refuses the job (user levels).
    bool newJob(const cutcell::Job& job, QString* why = nullptr);
    // Another window's document as it was: the job (with its unsaved edits), its file and its
    // modified mark (a rebuild of the window, ui/window_host.h).
    void adopt(const cutcell::Job& job, const QString& path, bool modified);
    bool open(const QString& path, QString* error);
    bool save(QString* error); // to path(); fails when there is none
    bool saveAs(const QString& path, QString* error);

    QStringList recentFiles() const;
    void clearRecentFiles();
    static constexpr int kMaxRecent = 8;

  signals:
    void changed(); // path or modified flag changed
    void recentFilesChanged();

  private:
    void setModified(bool m);
    void addRecent(const QString& path);

    JobEditor* editor_;
    QString path_;
    bool modified_ = false;
};

} // namespace CutCell::ui
