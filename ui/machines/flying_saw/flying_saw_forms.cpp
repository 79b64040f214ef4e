#include "ui/machines/flying_saw/flying_saw_forms.h"
#include "ui/forms/issue_text.h"
#include "ui/shown_number.h"

#include "ui/forms/number_fields.h"

#include "core/machines/flying_saw/flying_saw_section.h"
#include "core/machines/flying_saw/flying_saw_source.h"
#include "core/machines/flying_saw/flying_saw_spec.h"
#include "ui/forms/edited_spec.h"
#include "ui/run_controller.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace CutCell::ui {

using cutcell::FlyingSawSpec;
using cutcell::Job;
using cutcell::TubeShape;

namespace {

FlyingSawSpec& spec(Job& j) {
    return CutCell::ui::editedSpec<FlyingSawSpec>(j); // a scratch spec for another machine's job
}
const FlyingSawSpec* specOf(const Job& j) {
    return j.machine_spec.as<FlyingSawSpec>();
}

// 0 round, 1 square (a rectangle with a = b), 2 rectangular: the core knows round and
// rectangular; a square is the rectangle whose height follows its width.
int shapeIndex(const FlyingSawSpec& s) {
    if (s.shape == TubeShape::Round) return 0;
    return s.width_mm == s.height_mm ? 1 : 2;
}

// A limit the validator checks: the box takes any number, the message says what is wrong.
QDoubleSpinBox* cellLength(QWidget* parent) {
    auto* w = new DecimalField(parent);
    w->setFieldName(FlyingSawTubeLineForm::tr("length"));
    w->setDecimals(1);
    w->setRange(-1e9, 1e9);
    w->setButtonSymbols(QAbstractSpinBox::NoButtons);
    w->setAlignment(Qt::AlignRight);
    return w;
}
QSpinBox* cellCount(QWidget* parent) {
    auto* w = new WholeNumberField(parent);
    w->setFieldName(FlyingSawTubeLineForm::tr("pieces"));
    w->setRange(-1000000000, 1000000000);
    w->setButtonSymbols(QAbstractSpinBox::NoButtons);
    w->setAlignment(Qt::AlignRight);
    return w;
}

} // namespace

FlyingSawTubeLineForm::FlyingSawTubeLineForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    auto* note = new QLabel(
        tr("The tube leaves the mill continuously; the carriage meets it at each cut position, "
           "rides with it while the turntable's two blades cut, and returns. A length changed "
           "in the queue applies from the next piece."),
        this);
    note->setWordWrap(true);
    mainLayout()->addWidget(note);
    // One row per key: label, unit and decimals from the section's table.
    const auto row = [this](QFormLayout* form, const char* key) {
        return qobject_cast<QDoubleSpinBox*>(
            addSectionRow(form, sectionField(cutcell::flyingSawFields(), key), &spec));
    };

    auto* tube = new QGroupBox(tr("Tube (cut plane)"), this);
    tubeRows_ = new QFormLayout(tube);
    addRow(tubeRows_, tr("Shape"),
           shape_ = bindChoice(
               "tube.shape", {tr("Round (D)"), tr("Square (a × a)"), tr("Rectangular (a × b)")},
               [](const Job& j) {
                   const FlyingSawSpec* s = specOf(j);
                   return s ? shapeIndex(*s) : 1;
               },
               [](Job& j, int i) {
                   FlyingSawSpec& s = spec(j);
                   s.shape = i == 0 ? TubeShape::Round : TubeShape::Rectangular;
                   if (i == 1) s.height_mm = s.width_mm;
               }),
           "");
    diameterRow_ = tubeRows_->rowCount();
    row(tubeRows_, "tube.diameter_mm");
    widthRow_ = tubeRows_->rowCount();
    width_ = row(tubeRows_, "tube.width_mm");
    heightRow_ = tubeRows_->rowCount();
    height_ = row(tubeRows_, "tube.height_mm");
    cornerRow_ = tubeRows_->rowCount();
    row(tubeRows_, "tube.corner_radius_mm");
    row(tubeRows_, "tube.wall_mm");
    mainLayout()->addWidget(tube);
    connect(shape_, &QComboBox::currentIndexChanged, this, [this](int i) {
        showShapeRows(i);
        if (i == 1 && !loading()) {
            const QSignalBlocker block(height_);
            height_->setValue(width_->value());
        }
    });
    // A square's height follows its width.
    connect(width_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (loading() || shape_->currentIndex() != 1) return;
        {
            const QSignalBlocker block(height_);
            height_->setValue(v);
        }
        Job current = this->editor()->job();
        commit("tube.height_mm", QString::number(spec(current).height_mm, 'g', 12),
               QString::number(v, 'g', 12), [v](Job& j) { spec(j).height_mm = v; });
    });

    auto* line = new QGroupBox(tr("Line and measuring roller"), this);
    auto* fl = new QFormLayout(line);
    row(fl, "line.speed_m_min");
    addRow(fl, tr("Roller pulses per revolution"),
           bindInt("line.roller_pulses_per_rev",
                   [](Job& j) -> int& { return spec(j).roller_pulses_per_rev; }),
           tr("pulses/rev"));
    row(fl, "line.roller_diameter_mm");
    resolution_ = new QLabel(line);
    resolution_->setObjectName("sawEncoderResolution");
    resolution_->setWordWrap(true); // "0,05 mm pro Impuls (π D / Impulse)" on one line: too wide
    fl->addRow(tr("Encoder resolution"), resolution_);
    row(fl, "line.filter_alpha");
    mainLayout()->addWidget(line);

    auto* cut = queueGroup_ = new QGroupBox(tr("Pieces: the queue of cut lengths"), this);
    auto* vc = new QVBoxLayout(cut);
    queue_ = new QTableWidget(0, 2, cut);
    queue_->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    queue_->setObjectName("sawQueue");
    queue_->setHorizontalHeaderLabels({tr("Length (mm)"), tr("Count (pieces)")});
    queue_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    queue_->verticalHeader()->setDefaultSectionSize(26);
    queue_->setMinimumHeight(120);
    queue_->setSelectionBehavior(QAbstractItemView::SelectRows);
    vc->addWidget(queue_);
    auto* buttons = new QHBoxLayout;
    auto* add = new QPushButton(tr("Add length"), cut);
    add->setObjectName("sawQueueAdd");
    auto* remove = new QPushButton(tr("Remove selected"), cut);
    remove->setObjectName("sawQueueRemove");
    queueTotal_ = new QLabel(cut);
    queueTotal_->setWordWrap(true); // beside the German buttons it made the page too wide
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addWidget(queueTotal_, 1);
    vc->addLayout(buttons);
    alsoMark("cut.queue", queue_);
    for (int i = 0; i < 16; ++i) { // the core's queue holds up to 16 entries
        const std::string k = "cut.queue[" + std::to_string(i) + "]";
        alsoMark(k + ".length_mm", queue_);
        alsoMark(k + ".count", queue_);
    }
    connect(add, &QPushButton::clicked, this, [this] {
        const int n = queue_->rowCount();
        double last = 6000;
        if (n > 0)
            if (auto* w = qobject_cast<QDoubleSpinBox*>(queue_->cellWidget(n - 1, 0)))
                last = w->value();
        addQueueRow(last, 1);
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        int selected = queue_->currentRow();
        if (selected < 0) selected = queue_->rowCount() - 1;
        if (selected < 0) return;
        removeQueueRow(selected);
        writeQueue();
    });
    send_ = new QPushButton(tr("Send the queue to the running line (from the next piece)"), cut);
    send_->setObjectName("sawQueueSend");
    send_->hide();
    sendNote_ = new QLabel(cut);
    sendNote_->setObjectName("sawQueueSendNote");
    sendNote_->setWordWrap(true);
    sendNote_->hide();
    vc->addWidget(send_);
    vc->addWidget(sendNote_);
    connect(send_, &QPushButton::clicked, this, [this] {
        QString why;
        sendQueueToRunningLine(&why);
    });
    auto* fc = new QFormLayout;
    tolerance_ = row(fc, "cut.tolerance_mm");
    vc->addLayout(fc);
    mainLayout()->addWidget(cut);
    mainLayout()->addStretch(1);
    connect(editor, &JobEditor::edited, this, [this] { updateDerived(this->editor()->job()); });
}

void FlyingSawTubeLineForm::setEditingLocked(bool locked) {
    setEnabled(true);
    for (QWidget* w : findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly))
        if (w != queueGroup_ && w->objectName() != QLatin1String("formIssues"))
            w->setEnabled(!locked);
    tolerance_->setEnabled(!locked);
    send_->setVisible(locked);
    if (!locked) sendNote_->hide();
}

bool FlyingSawTubeLineForm::sendQueueToRunningLine(QString* why) {
    const auto refuse = [&](const QString& text) {
        sendNote_->setText(text);
        sendNote_->show();
        if (why) *why = text;
        return false;
    };
    const RunController* run = window()->findChild<RunController*>();
    const auto program = run ? run->program() : nullptr;
    auto* source =
        program ? dynamic_cast<cutcell::FlyingSawSource*>(program->source.get()) : nullptr;
    if (!source) return refuse(tr("Not sent: no flying-saw program is loaded."));
    for (const cutcell::JobIssue& issue : editor()->issues())
        if (issue.key.rfind("cut.queue", 0) == 0)
            return refuse(tr("Not sent: %1").arg(issueText(issue, QString())));
    const FlyingSawSpec* s = specOf(editor()->job());
    if (!s || s->queue.empty()) return refuse(tr("Not sent: the queue is empty."));
    if (s->queue.size() > cutcell::PieceQueue::kCapacity)
        return refuse(tr("Not sent: the queue has %1 entries; the line takes up to %2.")
                          .arg(s->queue.size())
                          .arg(cutcell::PieceQueue::kCapacity));
    cutcell::PieceQueue* q = source->queue().beginWrite();
    if (!q)
        return refuse(tr("Not sent: the previous change is not taken yet (it is, when the "
                         "carriage is back at its wait position)."));
    q->size = 0;
    for (const cutcell::PieceOrder& o : s->queue)
        q->entries[static_cast<size_t>(q->size++)] = {o.length_mm, o.count};
    source->queue().publish();
    int pieces = 0;
    for (const cutcell::PieceOrder& o : s->queue)
        pieces += o.count;
    sendNote_->setText(
        tr("Sent: %1 pieces replace the pieces not begun yet, from the next piece.").arg(pieces));
    sendNote_->show();
    return true;
}

void FlyingSawTubeLineForm::showShapeRows(int shape) {
    tubeRows_->setRowVisible(diameterRow_, shape == 0);
    tubeRows_->setRowVisible(widthRow_, shape != 0);
    tubeRows_->setRowVisible(heightRow_, shape != 0);
    tubeRows_->setRowVisible(cornerRow_, shape != 0);
    height_->setEnabled(shape == 2);
}

void FlyingSawTubeLineForm::reloadExtra(const Job& job) {
    const FlyingSawSpec* s = specOf(job);
    showShapeRows(s ? shapeIndex(*s) : 1);
    loadQueue(job);
    updateDerived(job);
}

void FlyingSawTubeLineForm::addQueueRow(double length_mm, int count) {
    appendQueueRow(length_mm, count);
    writeQueue();
}

void FlyingSawTubeLineForm::appendQueueRow(double length_mm, int count) {
    const int row = queue_->rowCount();
    queue_->insertRow(row);
    auto* length = cellLength(queue_);
    auto* pieces = cellCount(queue_);
    length->setValue(length_mm);
    pieces->setValue(count);
    length->setObjectName(QStringLiteral("sawQueueLength%1").arg(row));
    pieces->setObjectName(QStringLiteral("sawQueueCount%1").arg(row));
    queue_->setCellWidget(row, 0, length);
    queue_->setCellWidget(row, 1, pieces);
    connect(length, &QDoubleSpinBox::valueChanged, this, [this] { writeQueue(); });
    connect(pieces, &QSpinBox::valueChanged, this, [this] { writeQueue(); });
}

void FlyingSawTubeLineForm::loadQueue(const Job& job) {
    const FlyingSawSpec* s = specOf(job);
    const int n = s ? static_cast<int>(s->queue.size()) : 0;
    while (queue_->rowCount() > n)
        removeQueueRow(queue_->rowCount() - 1);
    for (int r = 0; r < n; ++r) {
        const cutcell::PieceOrder& o = s->queue[static_cast<size_t>(r)];
        if (r == queue_->rowCount()) {
            appendQueueRow(o.length_mm, o.count);
            continue;
        }
        auto* length = qobject_cast<QDoubleSpinBox*>(queue_->cellWidget(r, 0));
        auto* pieces = qobject_cast<QSpinBox*>(queue_->cellWidget(r, 1));
        const QSignalBlocker b1(length), b2(pieces);
        length->setValue(o.length_mm);
        pieces->setValue(o.count);
    }
}

void FlyingSawTubeLineForm::removeQueueRow(int row) {
    // The table deletes its cell widgets later: silence them and free their names now.
    for (int c = 0; c < 2; ++c)
        if (QWidget* w = queue_->cellWidget(row, c)) {
            w->blockSignals(true);
            w->setObjectName(QString());
        }
    queue_->removeRow(row);
    for (int r = row; r < queue_->rowCount(); ++r) {
        queue_->cellWidget(r, 0)->setObjectName(QStringLiteral("sawQueueLength%1").arg(r));
        queue_->cellWidget(r, 1)->setObjectName(QStringLiteral("sawQueueCount%1").arg(r));
    }
}

void FlyingSawTubeLineForm::writeQueue() {
    if (loading()) return;
    std::vector<cutcell::PieceOrder> q;
    for (int r = 0; r < queue_->rowCount(); ++r) {
        auto* length = qobject_cast<QDoubleSpinBox*>(queue_->cellWidget(r, 0));
        auto* pieces = qobject_cast<QSpinBox*>(queue_->cellWidget(r, 1));
        if (length && pieces) q.push_back({length->value(), pieces->value()});
    }
    const auto text = [](const std::vector<cutcell::PieceOrder>& orders) {
        QStringList parts;
        for (const cutcell::PieceOrder& o : orders)
            parts << QStringLiteral("%1 x %2")
                         .arg(QString::number(o.length_mm, 'g', 12))
                         .arg(o.count);
        return parts.join(QStringLiteral("; "));
    };
    Job current = editor()->job();
    commit("cut.queue", text(spec(current).queue), text(q), [&q](Job& j) { spec(j).queue = q; });
}

void FlyingSawTubeLineForm::updateDerived(const Job& job) {
    const FlyingSawSpec* s = specOf(job);
    if (!s) return;
    const double res = s->encoderResolutionMm();
    resolution_->setText(std::isfinite(res) && res > 0
                             ? tr("%1 mm per pulse (π D / pulses)").arg(shownSignificant(res, 4))
                             : tr("—"));
    double metres = 0;
    for (const cutcell::PieceOrder& o : s->queue)
        metres += o.length_mm * o.count / 1000.0;
    queueTotal_->setText(tr("%1 pieces, %2 m").arg(s->pieceCount()).arg(shownNumber(metres, 1)));
}

FlyingSawCarriageSawForm::FlyingSawCarriageSawForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    // One row per key: label, unit and decimals from the section's table.
    const auto row = [this](QFormLayout* form, const char* key) {
        return qobject_cast<QDoubleSpinBox*>(
            addSectionRow(form, sectionField(cutcell::flyingSawFields(), key), &spec));
    };
    // Ratios shown with what they are a fraction of (their table unit is a plain number).
    const auto dbl = [this](const char* key, int decimals, auto member) {
        return bindDouble(key, decimals, [member](Job& j) -> double& { return member(spec(j)); });
    };
    const auto group = [this](const QString& title) {
        auto* g = new QGroupBox(title, this);
        mainLayout()->addWidget(g);
        return new QFormLayout(g);
    };

    QFormLayout* fc = group(tr("Carriage (five periods: BC, CE, EF, FG-GH-HI)"));
    row(fc, "carriage.stroke_mm");
    row(fc, "carriage.wait_position_mm");
    row(fc, "carriage.max_speed_mm_s");
    row(fc, "carriage.max_accel_mm_s2");
    row(fc, "carriage.max_jerk_mm_s3");

    QFormLayout* fs = group(tr("Saw cycle in sync (C → D settle, feeds, half turn, retract)"));
    row(fs, "saw.settle_s");
    row(fs, "saw.fast_feed_mm_s");
    row(fs, "saw.slow_feed_mm_s");
    row(fs, "saw.approach_gap_mm");
    row(fs, "saw.overcut_mm");
    row(fs, "saw.clearance_mm");
    row(fs, "saw.retract_mm_s");
    row(fs, "saw.turntable_deg_s");
    row(fs, "saw.turntable_deg_s2");
    addRow(fs, tr("Cam table points per 180°"),
           bindInt("saw.table_points", [](Job& j) -> int& { return spec(j).saw.table_points; }),
           tr("points"));

    QFormLayout* fb = group(tr("Blade"));
    row(fb, "blade.diameter_mm");
    row(fb, "blade.kerf_mm");
    row(fb, "blade.rpm");

    QFormLayout* fg = group(tr("Length gauge after the saw (corrects the encoder scale)"));
    fg->addRow(QString(), bindBool("gauge.enabled", tr("Gauge on"),
                                   [](Job& j) -> bool& { return spec(j).gauge_enabled; }));
    addRow(fg, tr("Reports after"),
           bindInt("gauge.delay_pieces", [](Job& j) -> int& { return spec(j).gauge_delay_pieces; }),
           tr("pieces"));
    row(fg, "gauge.noise_mm");
    row(fg, "gauge.gain");

    QFormLayout* fv = group(tr("Simulated line and roller"));
    addRow(fv, tr("Speed wander ±"),
           dbl("line_sim.wander_fraction", 4,
               [](FlyingSawSpec& s) -> double& { return s.line_sim.wander_fraction; }),
           tr("of speed"));
    row(fv, "line_sim.wander_hz");
    addRow(fv, tr("Speed steps ±"),
           dbl("line_sim.step_fraction", 4,
               [](FlyingSawSpec& s) -> double& { return s.line_sim.step_fraction; }),
           tr("of speed"));
    row(fv, "line_sim.step_interval_s");
    row(fv, "line_sim.step_ramp_s");
    row(fv, "line_sim.noise_mm");
    addRow(fv, tr("Roller slip"),
           dbl("line_sim.slip_fraction", 5,
               [](FlyingSawSpec& s) -> double& { return s.line_sim.slip_fraction; }),
           tr("of travel"));
    mainLayout()->addStretch(1);
}

} // namespace CutCell::ui
