#pragma once
// The station's job queue (ui/job_queue.h) as a table - job, machine, source, received - with
// Open (the job becomes the one being edited, through the document's gates, so the operator
// checks it and presses Start) and Remove. A line above it says whether the shop floor is
// connected (the link's state, set by the app); "Link settings…" asks the app for the link's
// settings (issue 26: the engineer level where user levels exist).
//
// Threading contract: GUI thread only.
#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace CutCell::ui {

class JobQueue;
class JobDocument;

class JobQueuePanel : public QWidget {
    Q_OBJECT
  public:
    JobQueuePanel(JobQueue* queue, JobDocument* document, QWidget* parent = nullptr);

    void setLinkText(const QString& text);
    // Opens the queued job at `row` as the job being edited; false with why when the document
    // refuses it (a user level too low) or there is no such row. The entry leaves the queue.
    bool openQueued(int row, QString* why);
    QTableWidget* table() const { return table_; }
    // The "Link settings…" button: disabled with `why` as its tooltip when not allowed.
    void setSettingsAllowed(bool allowed, const QString& why);

  signals:
    void settingsRequested();

  private:
    void refresh();

    JobQueue* queue_;
    JobDocument* document_;
    QLabel* link_;
    QTableWidget* table_;
    QPushButton* open_;
    QPushButton* remove_;
    QPushButton* settings_;
    QLabel* message_;
};

} // namespace CutCell::ui
