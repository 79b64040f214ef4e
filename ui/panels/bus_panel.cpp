#include "ui/panels/bus_panel.h"
#include "ui/panels/engine_text.h"
#include "ui/shown_number.h"

#include <QFont>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace CutCell::ui {

using State = RigLink::State;

namespace {
enum Column { ColNode, ColNmt, ColState, ColHeartbeat, ColCount };

QString stateColor(State s) {
    switch (s) {
    case State::Up:
        return QStringLiteral("#2e9e44");
    case State::Connecting:
        return QStringLiteral("#d49a00");
    case State::Lost:
    case State::Failed:
        return QStringLiteral("#d0312d");
    default:
        return QStringLiteral("#8a8a8a");
    }
}
} // namespace

BusPanel::BusPanel(QWidget* parent)
    : QWidget(parent), state_(new QLabel(this)), detail_(new QLabel(this)),
      progress_(new QProgressBar(this)), nodes_(new QTableWidget(0, ColCount, this)),
      reconnect_(new QPushButton(tr("Reconnect"), this)) {
    nodes_->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    setObjectName("busPanel");
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(6, 4, 6, 4);
    v->setSpacing(3);
    auto* title = new QLabel(tr("CAN bus and nodes"), this);
    title->setObjectName("caption");
    auto* top = new QHBoxLayout;
    state_->setObjectName("busState");
    state_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    reconnect_->setObjectName("busReconnect");
    reconnect_->setFocusPolicy(Qt::NoFocus);
    top->addWidget(state_, 1);
    top->addWidget(reconnect_);
    detail_->setObjectName("busDetail");
    detail_->setWordWrap(true);
    // A long failure (six node reasons) must not push the column around: the tooltip has it all.
    detail_->setMaximumHeight(4 * fontMetrics().lineSpacing());
    detail_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    progress_->setObjectName("busProgress");
    progress_->setMaximumHeight(12);
    progress_->setTextVisible(false);
    nodes_->setObjectName("busNodes");
    nodes_->setHorizontalHeaderLabels({tr("Node"), tr("NMT"), tr("CiA 402"), tr("HB ms")});
    nodes_->verticalHeader()->hide();
    nodes_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    nodes_->setSelectionMode(QAbstractItemView::NoSelection);
    nodes_->setFocusPolicy(Qt::NoFocus);
    nodes_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    nodes_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    nodes_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    nodes_->horizontalHeader()->setSectionResizeMode(ColState, QHeaderView::Stretch);
    nodes_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 4);
    v->addWidget(title);
    v->addLayout(top);
    v->addWidget(progress_);
    v->addWidget(detail_);
    v->addWidget(nodes_);
    connect(reconnect_, &QPushButton::clicked, this, &BusPanel::reconnectRequested);
    setLink({});
}

void BusPanel::setLink(const RigLink& link) {
    link_ = link;
    setVisible(link.state != State::None);
    progress_->setVisible(link.state == State::Connecting);
    progress_->setRange(0, std::max(1, link.nodes));
    progress_->setValue(link.nodes_ready);
    reconnect_->setText(link.state == State::Down ? tr("Connect") : tr("Reconnect"));
    reconnect_->setEnabled(link.state != State::Connecting && link.state != State::None);
    refreshRows();
}

// The link's state in the GUI's language ("up", "lost" ...: the engine's words are English).
static QString linkStateWord(RigLink::State s) {
    switch (s) {
    case RigLink::State::None:
        return BusPanel::tr("none");
    case RigLink::State::Down:
        return BusPanel::tr("down");
    case RigLink::State::Connecting:
        return BusPanel::tr("connecting");
    case RigLink::State::Up:
        return BusPanel::tr("up");
    case RigLink::State::Lost:
        return BusPanel::tr("lost");
    case RigLink::State::Failed:
        return BusPanel::tr("failed");
    }
    return QStringLiteral("?");
}

void BusPanel::refreshState() {
    const QString where = QString::fromStdString(link_.where);
    QString state = tr("Bus %1").arg(linkStateWord(link_.state)).toUpper();
    QString text = engineText(QString::fromStdString(link_.text));
    QString color = stateColor(link_.state);
    QStringList silent;
    for (int r = 0; r < nodes_->rowCount(); ++r)
        if (rowStale(r)) silent << QString::number(snapshot_.nodes[static_cast<size_t>(r)].node);
    if (link_.state == State::Up && !silent.isEmpty()) {
        state = tr("BUS UP - %1 OF %2 NODES SILENT").arg(silent.size()).arg(nodes_->rowCount());
        text = tr("No heartbeat within %1 ms from node(s) %2: check their power and cable.")
                   .arg(shownNumber(snapshot_.heartbeat_timeout_ms, 0))
                   .arg(silent.join(QStringLiteral(", ")));
        color = stateColor(State::Lost);
    }
    state_->setText(state);
    state_->setToolTip(where);
    state_->setStyleSheet(QStringLiteral("font-weight: bold; color: %1").arg(color));
    detail_->setText(text);
    detail_->setToolTip(text);
}

void BusPanel::setSnapshot(const cutcell::ui::DevicePanelSnapshot& snapshot) {
    snapshot_ = snapshot;
    refreshRows();
}

bool BusPanel::rowStale(int row) const {
    return row >= 0 && static_cast<size_t>(row) < stale_.size() && stale_[static_cast<size_t>(row)];
}

void BusPanel::refreshRows() {
    const auto& nodes = snapshot_.nodes;
    nodes_->setRowCount(snapshot_.can ? static_cast<int>(nodes.size()) : 0);
    stale_.assign(static_cast<size_t>(nodes_->rowCount()), false);
    const QColor normal = palette().color(QPalette::Text);
    for (int r = 0; r < nodes_->rowCount(); ++r) {
        const auto& n = nodes[static_cast<size_t>(r)];
        // Stale: no heartbeat yet, or none within the timeout (the node or the bus is gone).
        const bool stale =
            n.heartbeat_age_ms < 0 || (snapshot_.heartbeat_timeout_ms > 0 &&
                                       n.heartbeat_age_ms > snapshot_.heartbeat_timeout_ms);
        stale_[static_cast<size_t>(r)] = stale;
        const QString hb = n.heartbeat_age_ms < 0      ? tr("none")
                           : n.heartbeat_age_ms > 9999 ? tr(">9999")
                                                       : shownNumber(n.heartbeat_age_ms, 0);
        const QString cells[ColCount] = {QString::number(n.node), engineText(n.nmt),
                                         engineText(n.cia402), hb};
        QString tip = tr("node %1, axis %2").arg(n.node).arg(n.axis);
        if (!n.fault.isEmpty()) tip += QStringLiteral("\n") + engineText(n.fault);
        if (!n.last_emcy.isEmpty()) tip += QStringLiteral("\n") + engineText(n.last_emcy);
        for (int c = 0; c < ColCount; ++c) {
            QTableWidgetItem* item = nodes_->item(r, c);
            if (!item) {
                item = new QTableWidgetItem;
                nodes_->setItem(r, c, item);
            }
            item->setText(cells[c]);
            item->setToolTip(tip);
            item->setForeground(stale     ? QColor(0x80, 0x80, 0x80)
                                : n.error ? QColor(0xd0, 0x31, 0x2d)
                                          : normal);
            QFont f = item->font();
            f.setItalic(stale);
            item->setFont(f);
        }
    }
    // Every row on screen, no scroll bar: the table is as tall as its rows.
    int h = nodes_->horizontalHeader()->height() + 2 * nodes_->frameWidth();
    for (int r = 0; r < nodes_->rowCount(); ++r)
        h += nodes_->rowHeight(r);
    nodes_->setFixedHeight(h);
    nodes_->setVisible(nodes_->rowCount() > 0);
    refreshState();
}

} // namespace CutCell::ui
