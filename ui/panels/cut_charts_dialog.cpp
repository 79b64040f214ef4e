#include "ui/panels/cut_charts_dialog.h"

#include "core/common/c_format.h"
#include "core/process/cut_chart_library.h"
#include "core/process/process_spec.h"
#include "core/record/audit.h"
#include "ui/access_control.h"
#include "ui/forms/number_fields.h"
#include "ui/forms/process_form.h"
#include "ui/shown_number.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <array>
#include <exception>

namespace CutCell::ui {

using cutcell::CutChart;
using cutcell::CutChartError;
using cutcell::CutFigure;
using cutcell::CutProcess;

namespace {

constexpr std::array<CutProcess, 3> kProcesses{CutProcess::Plasma, CutProcess::OxyFuel,
                                               CutProcess::Laser};

// A figure as the table shows it: the GUI language's decimal mark, no trailing zeros.
QString cellText(double v) {
    return shownSignificant(v, 10);
}

QString fromStd(const std::string& s) {
    return QString::fromStdString(s);
}

} // namespace

QString cutChartsLockReason(const AccessControl* access) {
    using cutcell::UserLevel;
    if (!access || access->singleUser()) return {};
    const QString setter = userLevelText(UserLevel::Setter);
    if (!access->level())
        return CutChartsDialog::tr("Log in to edit the cut charts (needs the %1 level).")
            .arg(setter);
    if (*access->level() >= UserLevel::Setter) return {};
    return CutChartsDialog::tr("Editing the cut charts needs the %1 level (%2 is logged in as %3).")
        .arg(setter, access->user(), userLevelText(*access->level()));
}

QString installCutChartsInUse(const std::string& dataHome) {
    static const QString answer = [&dataHome] {
        try {
            cutcell::CutChartsInUse inUse = cutcell::loadCutChartsInUse(dataHome);
            if (inUse.user) cutcell::setActiveCutCharts(std::move(inUse.set));
            return QString();
        } catch (const std::exception& e) {
            return QString::fromUtf8(e.what());
        }
    }();
    return answer;
}

CutChartsDialog::CutChartsDialog(std::string dataHome, AccessControl* access, QWidget* parent)
    : QDialog(parent), dataHome_(std::move(dataHome)), path_(cutcell::userCutChartsPath(dataHome_)),
      access_(access), where_(new QLabel(this)), lock_(new QLabel(this)),
      process_(new QComboBox(this)), material_(new QComboBox(this)),
      consumable_(new QComboBox(this)), rows_(new QTableWidget(this)), problem_(new QLabel(this)),
      status_(new QLabel(this)), add_(new QPushButton(tr("Add row"), this)),
      remove_(new QPushButton(tr("Remove row"), this)), save_(new QPushButton(tr("Save"), this)),
      close_(new QPushButton(tr("Close"), this)) {
    setObjectName("cutChartsDialog");
    setWindowTitle(tr("Cut charts"));
    try {
        cutcell::CutChartsInUse inUse = cutcell::loadCutChartsInUse(dataHome_);
        table_ = std::move(inUse.set);
        where_->setText(inUse.user ? tr("The user's table: %1").arg(fromStd(path_))
                                   : tr("The shipped table (a save writes the user's table %1, "
                                        "used from then on).")
                                         .arg(fromStd(path_)));
    } catch (const std::exception& e) {
        // A user's file that does not read is never overwritten from here: it is shown as the
        // shipped table, read-only, until it is fixed or removed.
        table_ = cutcell::shippedCutCharts();
        loadProblem_ = tr("The user's table %1 cannot be read (%2); fix or remove it. The "
                          "shipped table is shown.")
                           .arg(fromStd(path_), QString::fromUtf8(e.what()));
        where_->setText(loadProblem_);
    }
    where_->setObjectName("cutChartsWhere");
    where_->setWordWrap(true);
    where_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lock_->setObjectName("cutChartsLock");
    lock_->setWordWrap(true);
    process_->setObjectName("cutChartsProcess");
    material_->setObjectName("cutChartsMaterial");
    consumable_->setObjectName("cutChartsConsumable");
    for (const CutProcess p : kProcesses)
        process_->addItem(ProcessForm::processTitle(p));
    rows_->setObjectName("cutChartsRows");
    rows_->setTabKeyNavigation(false); // Tab leaves the table for the buttons
    rows_->verticalHeader()->hide();
    rows_->setSelectionBehavior(QAbstractItemView::SelectRows);
    rows_->setSelectionMode(QAbstractItemView::SingleSelection);
    rows_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    rows_->horizontalHeader()->setStretchLastSection(true);
    problem_->setObjectName("cutChartsProblem");
    problem_->setWordWrap(true);
    problem_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    problem_->setProperty("invalid", true); // the stylesheet's warning colour
    problem_->hide();
    status_->setObjectName("cutChartsStatus");
    status_->setWordWrap(true);
    add_->setObjectName("cutChartsAddRow");
    remove_->setObjectName("cutChartsRemoveRow");
    save_->setObjectName("cutChartsSave");
    close_->setObjectName("cutChartsClose");
    save_->setAutoDefault(false);
    add_->setAutoDefault(false);
    remove_->setAutoDefault(false);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(where_);
    layout->addWidget(lock_);
    auto* pick = new QFormLayout;
    pick->addRow(ProcessForm::tr("Process"), process_);
    pick->addRow(ProcessForm::tr("Material"), material_);
    pick->addRow(ProcessForm::tr("Consumable set"), consumable_);
    layout->addLayout(pick);
    layout->addWidget(rows_, 1);
    layout->addWidget(problem_);
    layout->addWidget(status_);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(add_);
    buttons->addWidget(remove_);
    buttons->addStretch(1);
    buttons->addWidget(save_);
    buttons->addWidget(close_);
    layout->addLayout(buttons);
    resize(720, 480);

    connect(process_, &QComboBox::currentIndexChanged, this, [this] {
        if (!filling_) fillMaterials();
    });
    connect(material_, &QComboBox::currentIndexChanged, this, [this] {
        if (!filling_) fillConsumables();
    });
    connect(consumable_, &QComboBox::currentIndexChanged, this, [this] {
        if (!filling_) showRows();
    });
    connect(rows_, &QTableWidget::itemChanged, this, &CutChartsDialog::cellEdited);
    connect(add_, &QPushButton::clicked, this, &CutChartsDialog::addRow);
    connect(remove_, &QPushButton::clicked, this, &CutChartsDialog::removeRow);
    connect(save_, &QPushButton::clicked, this, &CutChartsDialog::save);
    connect(close_, &QPushButton::clicked, this, &CutChartsDialog::reject);
    if (access_) connect(access_, &AccessControl::changed, this, &CutChartsDialog::applyAccess);

    // The first process that has a chart.
    for (std::size_t i = 0; i < kProcesses.size(); ++i)
        if (!table_.materials(kProcesses[i]).empty()) {
            filling_ = true;
            process_->setCurrentIndex(static_cast<int>(i));
            filling_ = false;
            break;
        }
    fillMaterials();
}

QString CutChartsDialog::lockReason() const {
    if (!loadProblem_.isEmpty()) return loadProblem_;
    return cutChartsLockReason(access_);
}

QString CutChartsDialog::problem() const {
    return problem_->isHidden() ? QString() : problem_->text();
}

std::optional<std::size_t> CutChartsDialog::chartIndex() const {
    const int p = process_->currentIndex();
    if (p < 0 || material_->currentIndex() < 0 || consumable_->currentIndex() < 0) return {};
    const CutProcess process = kProcesses[static_cast<std::size_t>(p)];
    const std::string m = material_->currentText().toStdString();
    const std::string c = consumable_->currentText().toStdString();
    for (std::size_t i = 0; i < table_.charts.size(); ++i) {
        const CutChart& chart = table_.charts[i];
        if (chart.process == process && chart.material == m && chart.consumable == c) return i;
    }
    return {};
}

bool CutChartsDialog::showChart(CutProcess p, const std::string& material,
                                const std::string& consumable) {
    if (!table_.find(p, material, consumable)) return false;
    filling_ = true;
    for (std::size_t i = 0; i < kProcesses.size(); ++i)
        if (kProcesses[i] == p) process_->setCurrentIndex(static_cast<int>(i));
    filling_ = false;
    fillMaterials();
    filling_ = true;
    material_->setCurrentIndex(material_->findText(fromStd(material)));
    filling_ = false;
    fillConsumables();
    filling_ = true;
    consumable_->setCurrentIndex(consumable_->findText(fromStd(consumable)));
    filling_ = false;
    showRows();
    return true;
}

void CutChartsDialog::fillMaterials() {
    const int p = process_->currentIndex();
    filling_ = true;
    const QString was = material_->currentText();
    material_->clear();
    if (p >= 0)
        for (const std::string& m : table_.materials(kProcesses[static_cast<std::size_t>(p)]))
            material_->addItem(fromStd(m));
    material_->setCurrentIndex(std::max(0, material_->findText(was)));
    filling_ = false;
    fillConsumables();
}

void CutChartsDialog::fillConsumables() {
    const int p = process_->currentIndex();
    filling_ = true;
    const QString was = consumable_->currentText();
    consumable_->clear();
    if (p >= 0 && material_->currentIndex() >= 0)
        for (const std::string& c : table_.consumables(kProcesses[static_cast<std::size_t>(p)],
                                                       material_->currentText().toStdString()))
            consumable_->addItem(fromStd(c));
    consumable_->setCurrentIndex(std::max(0, consumable_->findText(was)));
    filling_ = false;
    showRows();
}

void CutChartsDialog::showRows() {
    filling_ = true;
    const auto chart = chartIndex();
    rows_->clear();
    rows_->setRowCount(0);
    rows_->setColumnCount(0);
    if (chart) {
        const CutChart& c = table_.charts[*chart];
        rows_->setColumnCount(static_cast<int>(c.columns.size()));
        for (std::size_t k = 0; k < c.columns.size(); ++k) {
            const auto& info = cutcell::cutFigureInfo(c.columns[k]);
            auto* header = new QTableWidgetItem(ProcessForm::figureHeader(c.columns[k]));
            header->setToolTip(fromStd(info.key));
            rows_->setHorizontalHeaderItem(static_cast<int>(k), header);
        }
        rows_->setRowCount(static_cast<int>(c.rows.size()));
        for (std::size_t r = 0; r < c.rows.size(); ++r)
            for (std::size_t k = 0; k < c.columns.size(); ++k) {
                auto* item = new QTableWidgetItem(cellText(*c.rows[r].get(c.columns[k])));
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                rows_->setItem(static_cast<int>(r), static_cast<int>(k), item);
            }
        status_->setText(tr("Source: %1").arg(fromStd(c.source)));
    } else {
        status_->setText(tr("No chart for this choice."));
    }
    filling_ = false;
    applyAccess();
}

void CutChartsDialog::applyAccess() {
    const QString why = lockReason();
    const bool editable = why.isEmpty();
    lock_->setText(editable ? QString() : tr("Read-only: %1").arg(why));
    lock_->setVisible(!editable);
    filling_ = true;
    for (int r = 0; r < rows_->rowCount(); ++r)
        for (int c = 0; c < rows_->columnCount(); ++c)
            if (QTableWidgetItem* item = rows_->item(r, c))
                item->setFlags(editable ? item->flags() | Qt::ItemIsEditable
                                        : item->flags() & ~Qt::ItemIsEditable);
    filling_ = false;
    const bool chart = chartIndex().has_value();
    add_->setEnabled(editable && chart);
    remove_->setEnabled(editable && chart);
    save_->setEnabled(editable && modified_);
    for (QPushButton* b : {add_, remove_, save_})
        b->setToolTip(editable ? QString() : why);
}

void CutChartsDialog::setProblem(const QString& text) {
    problem_->setText(text);
    problem_->setVisible(!text.isEmpty());
}

void CutChartsDialog::took(const std::string& key, const QString& was, const QString& now,
                           const QString& unit) {
    modified_ = true;
    changes_.push_back({key, was, now, unit});
    setProblem({});
    status_->setText(tr("Changed; Save writes the user's table."));
    save_->setEnabled(lockReason().isEmpty());
}

void CutChartsDialog::cellEdited(QTableWidgetItem* item) {
    if (filling_ || !item) return;
    const auto chart = chartIndex();
    if (!chart) return;
    const auto r = static_cast<std::size_t>(item->row());
    const auto k = static_cast<std::size_t>(item->column());
    const CutChart& c = table_.charts[*chart];
    if (r >= c.rows.size() || k >= c.columns.size()) return;
    const CutFigure f = c.columns[k];
    const auto& info = cutcell::cutFigureInfo(f);
    const double old = *c.rows[r].get(f);
    const auto restore = [&] {
        filling_ = true;
        item->setText(cellText(old));
        filling_ = false;
    };
    if (const QString why = lockReason(); !why.isEmpty()) {
        setProblem(why);
        restore();
        return;
    }
    const TypedNumber typed = readTypedNumber(item->text().trimmed(), 6, true);
    if (typed.kind != TypedNumber::Kind::Number) {
        setProblem(tr("%1 = '%2' is not a number of %3%4")
                       .arg(fromStd(info.key), item->text(), fromStd(info.unit),
                            typed.why.isEmpty() ? QString() : QStringLiteral(": ") + typed.why));
        restore();
        return;
    }
    // "plasma / mild_steel / 45A at 6 mm: kerf_mm" (c is not used past the edit: the table
    // is replaced).
    const std::string key =
        cutcell::formatC("%s at %g mm: %s", c.name().c_str(), c.rows[r].thicknessMm(), info.key);
    try {
        table_ = cutcell::setCutChartFigure(table_, *chart, r, f, typed.value);
    } catch (const CutChartError& e) {
        setProblem(QString::fromUtf8(e.what())); // chart, row, field, value, unit and limit
        restore();
        return;
    }
    took(key, QString::number(old, 'g', 12), QString::number(typed.value, 'g', 12),
         fromStd(info.unit));
    filling_ = true;
    item->setText(cellText(typed.value));
    filling_ = false;
}

void CutChartsDialog::addRow() {
    const auto chart = chartIndex();
    if (!chart || !lockReason().isEmpty()) return;
    const CutChart& c = table_.charts[*chart];
    const int selected = rows_->currentRow();
    const std::size_t r = selected >= 0 && static_cast<std::size_t>(selected) < c.rows.size()
                              ? static_cast<std::size_t>(selected)
                              : c.rows.size() - 1;
    // Between the selected row and the next, interpolated as a pick would; after the last
    // row, its figures 1 mm thicker. Either is a start for the operator to edit.
    cutcell::CutRow row = c.rows[r];
    double t = c.rows[r].thicknessMm() + 1.0;
    if (r + 1 < c.rows.size()) {
        t = 0.5 * (c.rows[r].thicknessMm() + c.rows[r + 1].thicknessMm());
        row = cutcell::pickCutRow(c, t).row;
    }
    row.set(CutFigure::ThicknessMm, t);
    const std::string name = c.name();
    try {
        table_ = cutcell::addCutChartRow(table_, *chart, row);
    } catch (const CutChartError& e) {
        setProblem(QString::fromUtf8(e.what()));
        return;
    }
    // The trail's values are data, not translated.
    took(name, {}, QStringLiteral("row at %1 mm added").arg(QString::number(t, 'g', 12)), {});
    showRows();
    for (int i = 0; i < rows_->rowCount(); ++i)
        if (table_.charts[*chart].rows[static_cast<std::size_t>(i)].thicknessMm() == t)
            rows_->setCurrentCell(i, 0);
}

void CutChartsDialog::removeRow() {
    const auto chart = chartIndex();
    if (!chart || !lockReason().isEmpty()) return;
    const int selected = rows_->currentRow();
    if (selected < 0) {
        setProblem(tr("Select the row to remove."));
        return;
    }
    const CutChart& c = table_.charts[*chart];
    const double t = c.rows[static_cast<std::size_t>(selected)].thicknessMm();
    const std::string name = c.name();
    try {
        table_ = cutcell::removeCutChartRow(table_, *chart, static_cast<std::size_t>(selected));
    } catch (const CutChartError& e) {
        setProblem(QString::fromUtf8(e.what())); // the last row of a chart
        return;
    }
    took(name, QStringLiteral("row at %1 mm").arg(QString::number(t, 'g', 12)),
         QStringLiteral("removed"), {});
    showRows();
}

bool CutChartsDialog::save() {
    if (const QString why = lockReason(); !why.isEmpty()) {
        setProblem(why);
        return false;
    }
    try {
        cutcell::saveCutChartsFile(path_, table_);
        cutcell::setActiveCutCharts(table_);
    } catch (const std::exception& e) {
        setProblem(tr("Not saved: %1").arg(QString::fromUtf8(e.what())));
        return false;
    }
    if (access_)
        for (const Change& ch : changes_)
            access_->audit(cutcell::audit_event::kParameterChanged,
                           QStringLiteral("cut_charts: ") + fromStd(ch.key), ch.was, ch.now,
                           ch.unit, fromStd(path_));
    changes_.clear();
    modified_ = false;
    setProblem({});
    where_->setText(tr("The user's table: %1").arg(fromStd(path_)));
    status_->setText(tr("Saved to %1.").arg(fromStd(path_)));
    applyAccess();
    emit saved();
    return true;
}

void CutChartsDialog::reject() {
    if (modified_) {
        const auto answer = QMessageBox::question(
            this, tr("Cut charts"), tr("The cut charts have unsaved changes. Save them?"),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        if (answer == QMessageBox::Cancel) return;
        if (answer == QMessageBox::Save && !save()) return;
    }
    QDialog::reject();
}

} // namespace CutCell::ui
