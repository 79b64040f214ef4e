#include "ui/panels/job_queue_panel.h"

#include "ui/job_document.h"
#include "ui/job_queue.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace CutCell::ui {

JobQueuePanel::JobQueuePanel(JobQueue* queue, JobDocument* document, QWidget* parent)
    : QWidget(parent), queue_(queue), document_(document), link_(new QLabel(this)),
      table_(new QTableWidget(this)), open_(new QPushButton(tr("Open"), this)),
      remove_(new QPushButton(tr("Remove"), this)),
      settings_(new QPushButton(tr("Link settings…"), this)), message_(new QLabel(this)) {
    setObjectName("jobQueuePanel");
    auto* v = new QVBoxLayout(this);
    link_->setObjectName("jobQueueLink");
    link_->setWordWrap(true);
    v->addWidget(link_);
    table_->setObjectName("jobQueueTable");
    table_->setColumnCount(4);
    table_->setHorizontalHeaderLabels({tr("Job"), tr("Machine"), tr("From"), tr("Received")});
    table_->verticalHeader()->hide();
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setTabKeyNavigation(false);
    table_->horizontalHeader()->setStretchLastSection(true);
    v->addWidget(table_, 1);
    auto* buttons = new QHBoxLayout;
    open_->setObjectName("jobQueueOpen");
    remove_->setObjectName("jobQueueRemove");
    open_->setToolTip(tr("Make the selected job the one being edited; check it and press Start."));
    buttons->addWidget(open_);
    buttons->addWidget(remove_);
    buttons->addStretch(1);
    settings_->setObjectName("jobQueueLinkSettings");
    buttons->addWidget(settings_);
    v->addLayout(buttons);
    message_->setObjectName("jobQueueMessage");
    message_->setWordWrap(true);
    v->addWidget(message_);
    setLinkText(tr("Shop floor: off (no configuration; cutcell --shopfloor FILE)"));

    connect(queue_, &JobQueue::changed, this, &JobQueuePanel::refresh);
    connect(open_, &QPushButton::clicked, this, [this] {
        QString why;
        if (!openQueued(table_->currentRow(), &why)) message_->setText(why);
    });
    connect(remove_, &QPushButton::clicked, this, [this] { queue_->remove(table_->currentRow()); });
    connect(settings_, &QPushButton::clicked, this, &JobQueuePanel::settingsRequested);
    connect(table_, &QTableWidget::currentCellChanged, this, [this] {
        open_->setEnabled(table_->currentRow() >= 0);
        remove_->setEnabled(table_->currentRow() >= 0);
    });
    setSettingsAllowed(true, {});
    refresh();
}

void JobQueuePanel::setSettingsAllowed(bool allowed, const QString& why) {
    settings_->setEnabled(allowed);
    settings_->setToolTip(allowed ? tr("The shop-floor link's broker, identity and TLS files")
                                  : why);
}

void JobQueuePanel::setLinkText(const QString& text) {
    link_->setText(text);
}

bool JobQueuePanel::openQueued(int row, QString* why) {
    if (row < 0 || row >= queue_->size()) {
        if (why) *why = tr("Select a queued job first.");
        return false;
    }
    const JobQueue::Entry entry = queue_->entries()[static_cast<size_t>(row)];
    QString refused;
    if (!document_->newJob(entry.job, &refused)) {
        if (why) *why = tr("Not opened: %1").arg(refused);
        return false;
    }
    queue_->remove(row);
    message_->setText(tr("Opened '%1' from %2: check it, then press Start.")
                          .arg(QString::fromStdString(entry.job.name), entry.source));
    return true;
}

void JobQueuePanel::refresh() {
    const auto& entries = queue_->entries();
    table_->setRowCount(static_cast<int>(entries.size()));
    for (size_t i = 0; i < entries.size(); ++i) {
        const auto& e = entries[i];
        const QStringList cells{QString::fromStdString(e.job.name),
                                QString::fromStdString(e.job.machine), e.source,
                                QLocale().toString(e.received, QLocale::ShortFormat)};
        for (int c = 0; c < cells.size(); ++c)
            table_->setItem(static_cast<int>(i), c, new QTableWidgetItem(cells[c]));
    }
    open_->setEnabled(table_->currentRow() >= 0);
    remove_->setEnabled(table_->currentRow() >= 0);
}

} // namespace CutCell::ui
