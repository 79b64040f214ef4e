#include "ui/device_panel.h"
#include "ui/shown_number.h"

#include "ui/forms/number_fields.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace cutcell::ui {
namespace {
enum Column { ColNode, ColAxis, ColNmt, ColState, ColHeartbeat, ColEmcy, ColFault, ColCount };
}

DevicePanel::DevicePanel(QWidget* parent) : QWidget(parent) {
    kind_ = new QComboBox;
    kind_->addItem(tr("Simulated drives (in-process)"));
    kind_->addItem(tr("CANopen CiA 402 drives"));
    plugin_ = new QLineEdit;
    plugin_->setToolTip(tr("Qt CAN plugin: socketcan on a real bus, virtualcan for tests"));
    interface_ = new QLineEdit;
    auto* bitrate = new CutCell::ui::WholeNumberField;
    bitrate->setFieldName(tr("Bit rate"));
    bitrate_ = bitrate;
    bitrate_->setRange(10, 1000);
    bitrate_->setSuffix(tr(" kbit/s"));
    choiceBox_ = new QWidget;
    auto* form = new QFormLayout(choiceBox_);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Drives"), kind_);
    form->addRow(tr("CAN plugin"), plugin_);
    form->addRow(tr("Interface"), interface_);
    form->addRow(tr("Bit rate"), bitrate_);

    bus_ = new QLabel(tr("Bus: -"));
    bus_->setWordWrap(true); // a failure names every node: wrapped, never wider than the tab
    load_ = new QLabel(tr("Load: -"));
    load_->setWordWrap(true);
    nodes_ = new QTableWidget(0, ColCount);
    nodes_->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    nodes_->setHorizontalHeaderLabels({tr("Node"), tr("Axis"), tr("NMT"), tr("CiA 402"),
                                       tr("Heartbeat"), tr("Last EMCY"), tr("Fault")});
    nodes_->verticalHeader()->hide();
    nodes_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    nodes_->setSelectionMode(QAbstractItemView::NoSelection);
    nodes_->horizontalHeader()->setStretchLastSection(true);
    reset_ = new QPushButton(tr("Fault reset"));

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(choiceBox_);
    layout->addWidget(bus_);
    layout->addWidget(load_);
    layout->addWidget(nodes_, 1);
    layout->addWidget(reset_, 0, Qt::AlignRight);

    connect(kind_, &QComboBox::currentIndexChanged, this, [this] { emitChoice(); });
    connect(plugin_, &QLineEdit::editingFinished, this, [this] { emitChoice(); });
    connect(interface_, &QLineEdit::editingFinished, this, [this] { emitChoice(); });
    connect(bitrate_, &QSpinBox::valueChanged, this, [this] { emitChoice(); });
    connect(reset_, &QPushButton::clicked, this, &DevicePanel::faultResetRequested);
    setChoice({});
    setSnapshot({});
}

void DevicePanel::setChoiceVisible(bool visible) {
    choiceBox_->setVisible(visible);
}

void DevicePanel::setChoice(const DeviceChoice& c) {
    updating_ = true;
    kind_->setCurrentIndex(c.can ? 1 : 0);
    plugin_->setText(c.plugin);
    interface_->setText(c.interface);
    bitrate_->setValue(c.bitrate_bps / 1000);
    for (QWidget* w : {static_cast<QWidget*>(plugin_), static_cast<QWidget*>(interface_),
                       static_cast<QWidget*>(bitrate_)})
        w->setEnabled(c.can);
    updating_ = false;
}

DeviceChoice DevicePanel::choice() const {
    DeviceChoice c;
    c.can = kind_->currentIndex() == 1;
    c.plugin = plugin_->text().trimmed();
    c.interface = interface_->text().trimmed();
    c.bitrate_bps = bitrate_->value() * 1000;
    return c;
}

void DevicePanel::emitChoice() {
    if (updating_) return;
    const DeviceChoice c = choice();
    for (QWidget* w : {static_cast<QWidget*>(plugin_), static_cast<QWidget*>(interface_),
                       static_cast<QWidget*>(bitrate_)})
        w->setEnabled(c.can);
    emit choiceEdited(c);
}

void DevicePanel::setSnapshot(const DevicePanelSnapshot& s) {
    if (!s.can) {
        bus_->setText(tr("Bus: none (simulated in-process drives)"));
        load_->clear();
    } else {
        bus_->setText(tr("Bus: %1").arg(shown_(s.bus_state)));
        bus_->setStyleSheet(s.bus_error ? QStringLiteral("color: #b00020; font-weight: bold")
                                        : QString());
        load_->setText(tr("Load: %1 %").arg(CutCell::ui::shownNumber(s.load * 100, 1)));
        load_->setToolTip(shown_(s.load_text));
    }
    nodes_->setRowCount(static_cast<int>(s.nodes.size()));
    for (int r = 0; r < nodes_->rowCount(); ++r) {
        const DevicePanelNode& n = s.nodes[static_cast<size_t>(r)];
        const QString hb = n.heartbeat_age_ms < 0
                               ? tr("none")
                               : tr("%1 ms").arg(CutCell::ui::shownNumber(n.heartbeat_age_ms, 0));
        const QString cells[ColCount] = {QString::number(n.node), n.axis, shown_(n.nmt),
                                         shown_(n.cia402),        hb,     shown_(n.last_emcy),
                                         shown_(n.fault)};
        for (int c = 0; c < ColCount; ++c) {
            QTableWidgetItem* item = nodes_->item(r, c);
            if (!item) {
                item = new QTableWidgetItem;
                nodes_->setItem(r, c, item);
            }
            item->setText(cells[c]);
            item->setToolTip(cells[c]);
            item->setForeground(n.error ? QColor(0xb0, 0x00, 0x20)
                                        : palette().color(QPalette::Text));
        }
    }
    nodes_->resizeColumnsToContents();
    reset_->setEnabled(s.can || !s.nodes.empty());
}

} // namespace cutcell::ui
