#include "ui/forms/process_form.h"

#include "core/process/cut_chart_library.h"
#include "core/process/process_spec.h"
#include "ui/access_control.h"
#include "ui/forms/number_fields.h"
#include "ui/panels/cut_charts_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <optional>
#include <stdexcept>

namespace CutCell::ui {

using cutcell::CutFigure;
using cutcell::CutProcess;
using cutcell::Job;

namespace {

constexpr std::array<CutProcess, 3> kProcesses{CutProcess::Plasma, CutProcess::OxyFuel,
                                               CutProcess::Laser};

QString figureTitle(CutFigure f);

} // namespace

QString ProcessForm::processTitle(CutProcess p) {
    switch (p) {
    case CutProcess::Plasma:
        return ProcessForm::tr("Plasma");
    case CutProcess::OxyFuel:
        return ProcessForm::tr("Oxy-fuel");
    case CutProcess::Laser:
        return ProcessForm::tr("Laser");
    }
    return {};
}

QString ProcessForm::figureHeader(CutFigure f) {
    return figureTitle(f) + QStringLiteral(" [") + displayUnit(cutcell::cutFigureInfo(f).unit) +
           QStringLiteral("]");
}

namespace {

QString figureTitle(CutFigure f) {
    switch (f) {
    case CutFigure::ThicknessMm:
        return ProcessForm::tr("Thickness");
    case CutFigure::KerfMm:
        return ProcessForm::tr("Kerf width");
    case CutFigure::CutSpeedMmMin:
        return ProcessForm::tr("Cut speed");
    case CutFigure::PierceHeightMm:
        return ProcessForm::tr("Pierce height");
    case CutFigure::PierceDelayS:
        return ProcessForm::tr("Pierce delay");
    case CutFigure::CutHeightMm:
        return ProcessForm::tr("Cut height");
    case CutFigure::ArcVoltageV:
        return ProcessForm::tr("Arc voltage");
    case CutFigure::PreheatS:
        return ProcessForm::tr("Preheat");
    }
    return {};
}

std::string overrideKey(CutFigure f) {
    return std::string("process.override.") + cutcell::cutFigureInfo(f).key;
}

QString number(double v, int decimals) {
    return QLocale().toString(v, 'f', decimals);
}

int decimalsOf(CutFigure f) {
    return f == CutFigure::CutSpeedMmMin ? 0 : 2;
}

} // namespace

ProcessForm::ProcessForm(JobEditor* editor, ProcessPart part, QWidget* parent)
    : JobForm(editor, parent), part_(std::move(part)) {
    if (!part_.wallMm) throw std::logic_error("ProcessForm: no part wall");
    // The user's cut charts, when there are any, once per program (the first window).
    installCutChartsInUse(cutcell::defaultDataHome());
    auto* entry = new QGroupBox(tr("Cut chart"), this);
    auto* f = new QFormLayout(entry);
    used_ = new QCheckBox(tr("use a cut chart"), entry);
    used_->setObjectName("processUsed");
    alsoMark("process.used", used_);
    // The library's editor under the chart's choice (the page stays within its 424 px).
    editCharts_ = new QPushButton(tr("Cut charts…"), entry);
    editCharts_->setObjectName("processEditCharts");
    editCharts_->setToolTip(tr("View and edit the cut-chart library (the user's table; the "
                               "setter level and above may edit it)."));
    connect(editCharts_, &QPushButton::clicked, this, &ProcessForm::openCutCharts);
    f->addRow(tr("Process data"), used_);
    // Its own row: beside the check box it made the German page wider than its pane.
    auto* chartsRow = new QHBoxLayout;
    chartsRow->setContentsMargins(0, 0, 0, 0);
    chartsRow->addWidget(editCharts_);
    chartsRow->addStretch(1);
    f->addRow(QString(), chartsRow);
    process_ = new QComboBox(entry);
    process_->setObjectName("processKind");
    for (const CutProcess p : kProcesses)
        process_->addItem(processTitle(p));
    alsoMark("process.process", process_);
    addRow(f, tr("Process"), process_, {});
    material_ = new QComboBox(entry);
    material_->setObjectName("processMaterial");
    alsoMark("process.material", material_);
    addRow(f, tr("Material"), material_, {});
    consumable_ = new QComboBox(entry);
    consumable_->setObjectName("processConsumable");
    alsoMark("process.consumable", consumable_);
    addRow(f, tr("Consumable set"), consumable_, {});
    partWall_ = new QCheckBox(tr("the part's wall"), entry);
    partWall_->setObjectName("processPartWall");
    partWall_->setToolTip(part_.wallNote);
    f->addRow(tr("Thickness from"), partWall_);
    auto* thickness = new DecimalField(entry);
    thickness->setFieldName(QStringLiteral("process.thickness_mm"));
    thickness->setDecimals(2);
    thickness->setRange(-1e9, 1e9);
    thickness->setButtonSymbols(QAbstractSpinBox::NoButtons);
    thickness->setAlignment(Qt::AlignRight);
    thickness->setObjectName("processThickness");
    thickness_ = thickness;
    alsoMark("process.thickness_mm", thickness_);
    addRow(f, tr("Thickness"), thickness_, "mm");
    mainLayout()->addWidget(entry);

    auto* row = new QGroupBox(tr("Figures at this thickness"), this);
    auto* r = new QVBoxLayout(row);
    figures_ = new QTableWidget(row);
    figures_->setObjectName("processFigures");
    figures_->setColumnCount(4);
    figures_->setHorizontalHeaderLabels({tr("Figure"), tr("Chart"), tr("Override"), tr("Used")});
    figures_->verticalHeader()->hide();
    figures_->setTabKeyNavigation(false); // Tab leaves the table for the next field
    figures_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    figures_->horizontalHeader()->setSectionResizeMode(3, QHeaderView::Stretch);
    figures_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    r->addWidget(figures_);
    chart_ = new QLabel(row);
    chart_->setObjectName("processChart");
    chart_->setWordWrap(true);
    chart_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    r->addWidget(chart_);
    mainLayout()->addWidget(row);
    mainLayout()->addStretch(1);
    buildFigureRows();

    connect(used_, &QCheckBox::toggled, this, [this](bool on) {
        if (!refreshing_ && !loading()) setUsed(on);
    });
    connect(process_, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (refreshing_ || loading() || i < 0) return;
        const CutProcess p = kProcesses[static_cast<size_t>(i)];
        const auto& charts = cutcell::activeCutCharts();
        const auto materials = charts.materials(p);
        commit("process.process", cutcell::toString(JobForm::editor()->job().process.process),
               cutcell::toString(p), [&](Job& j) {
                   j.process.process = p;
                   j.process.material = materials.empty() ? std::string() : materials.front();
                   const auto sets = charts.consumables(p, j.process.material);
                   j.process.consumable = sets.empty() ? std::string() : sets.front();
                   j.process.override = {};
               });
    });
    connect(material_, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (refreshing_ || loading() || i < 0) return;
        const std::string m = material_->itemText(i).toStdString();
        const auto sets =
            cutcell::activeCutCharts().consumables(JobForm::editor()->job().process.process, m);
        commit("process.material",
               QString::fromStdString(JobForm::editor()->job().process.material),
               QString::fromStdString(m), [&](Job& j) {
                   j.process.material = m;
                   j.process.consumable = sets.empty() ? std::string() : sets.front();
               });
    });
    connect(consumable_, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (refreshing_ || loading() || i < 0) return;
        const std::string c = consumable_->itemText(i).toStdString();
        commit("process.consumable",
               QString::fromStdString(JobForm::editor()->job().process.consumable),
               QString::fromStdString(c), [&](Job& j) { j.process.consumable = c; });
    });
    connect(partWall_, &QCheckBox::toggled, this, [this](bool fromWall) {
        if (refreshing_ || loading()) return;
        const Job& job = JobForm::editor()->job();
        const double wall = partWallMm(job);
        const QString old = job.process.thickness_mm ? QString::number(*job.process.thickness_mm)
                                                     : QStringLiteral("part wall");
        commit("process.thickness_mm", old,
               fromWall ? QStringLiteral("part wall") : QString::number(wall), [&](Job& j) {
                   if (fromWall)
                       j.process.thickness_mm.reset();
                   else
                       j.process.thickness_mm = wall;
               });
    });
    connect(thickness_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (refreshing_ || loading() || !JobForm::editor()->job().process.thickness_mm) return;
        commit("process.thickness_mm",
               QString::number(*JobForm::editor()->job().process.thickness_mm),
               QString::number(v, 'g', 12), [&](Job& j) { j.process.thickness_mm = v; });
    });
    // Every edit may change the row (the pipes' walls, the target): show it again.
    connect(editor, &JobEditor::edited, this, [this] { reloadExtra(JobForm::editor()->job()); });
}

void ProcessForm::openCutCharts() {
    auto* dialog = new CutChartsDialog(cutcell::defaultDataHome(), AccessControl::current(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    const cutcell::ProcessSpec& p = JobForm::editor()->job().process;
    if (p.used) dialog->showChart(p.process, p.material, p.consumable);
    connect(dialog, &CutChartsDialog::saved, this, [this] {
        JobForm::editor()->cutChartsChanged();
        reloadExtra(JobForm::editor()->job());
    });
    dialog->open();
}

void ProcessForm::buildFigureRows() {
    figures_->setRowCount(static_cast<int>(cutcell::kCutFigureCount) - 1);
    for (std::size_t k = 1; k < cutcell::kCutFigureCount; ++k) {
        const auto f = static_cast<CutFigure>(k);
        const int row = static_cast<int>(k) - 1;
        const auto& info = cutcell::cutFigureInfo(f);
        auto* name = new QTableWidgetItem(figureHeader(f));
        name->setFlags(Qt::ItemIsEnabled);
        figures_->setItem(row, 0, name);
        auto* chart = new QTableWidgetItem;
        chart->setFlags(Qt::ItemIsEnabled);
        chart->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        figures_->setItem(row, 1, chart);
        auto* box = new QCheckBox(figures_);
        box->setObjectName(QStringLiteral("override_%1").arg(info.key));
        overrideBox_[k] = box;
        figures_->setCellWidget(row, 2, box);
        auto* value = new DecimalField(figures_);
        value->setFieldName(QString::fromStdString(overrideKey(f)));
        value->setDecimals(decimalsOf(f));
        value->setRange(-1e9, 1e9);
        value->setButtonSymbols(QAbstractSpinBox::NoButtons);
        value->setAlignment(Qt::AlignRight);
        value->setObjectName(QStringLiteral("value_%1").arg(info.key));
        value->setMinimumWidth(64);
        valueBox_[k] = value;
        figures_->setCellWidget(row, 3, value);
        alsoMark(overrideKey(f), value);
        connect(box, &QCheckBox::toggled, this, [this, k](bool on) {
            if (!refreshing_ && !loading()) setFigureOverridden(static_cast<int>(k), on);
        });
        connect(value, &QDoubleSpinBox::valueChanged, this, [this, k](double v) {
            if (!refreshing_ && !loading()) setFigureValue(static_cast<int>(k), v);
        });
    }
}

QString ProcessForm::refusal(CutFigure f) const {
    for (const auto& [figure, why] : part_.refused)
        if (figure == f) return why;
    return {};
}

void ProcessForm::setUsed(bool on) {
    commit("process.used", on ? QStringLiteral("false") : QStringLiteral("true"),
           on ? QStringLiteral("true") : QStringLiteral("false"), [&](Job& j) {
               j.process.used = on;
               if (!on || !j.process.material.empty()) return;
               // The first chart of the library as a start.
               const auto& charts = cutcell::activeCutCharts();
               if (charts.charts.empty()) return;
               const auto& first = charts.charts.front();
               j.process.process = first.process;
               j.process.material = first.material;
               j.process.consumable = first.consumable;
           });
}

void ProcessForm::setFigureOverridden(int figure, bool on) {
    const auto f = static_cast<CutFigure>(figure);
    const Job& job = JobForm::editor()->job();
    const cutcell::ProcessSettings s = cutcell::resolveProcess(job.process, partWallMm(job));
    // The override starts at the chart's figure (at its lower limit when the chart has none).
    const double start = s.chart_row.get(f).value_or(std::max(0.0, cutcell::cutFigureInfo(f).lo));
    const auto old = job.process.override.get(f);
    commit(overrideKey(f), old ? QString::number(*old) : QStringLiteral("chart"),
           on ? QString::number(start) : QStringLiteral("chart"), [&](Job& j) {
               if (on)
                   j.process.override.set(f, start);
               else
                   j.process.override.figures[static_cast<std::size_t>(figure)].reset();
           });
}

void ProcessForm::setFigureValue(int figure, double v) {
    const auto f = static_cast<CutFigure>(figure);
    const auto old = JobForm::editor()->job().process.override.get(f);
    if (!old) return;
    commit(overrideKey(f), QString::number(*old), QString::number(v, 'g', 12),
           [&](Job& j) { j.process.override.set(f, v); });
}

void ProcessForm::reloadExtra(const Job& job) {
    refreshing_ = true;
    const cutcell::ProcessSpec& p = job.process;
    const auto& charts = cutcell::activeCutCharts();
    used_->setChecked(p.used);
    for (QWidget* w : std::initializer_list<QWidget*>{process_, material_, consumable_, partWall_,
                                                      thickness_, figures_})
        w->setEnabled(p.used);
    for (size_t i = 0; i < kProcesses.size(); ++i)
        if (kProcesses[i] == p.process) process_->setCurrentIndex(static_cast<int>(i));
    auto fill = [](QComboBox* box, const std::vector<std::string>& items, const std::string& now) {
        box->clear();
        for (const auto& s : items)
            box->addItem(QString::fromStdString(s));
        // A name the library does not have (a job from another cell) stays visible, marked by
        // the validation.
        if (!now.empty() && box->findText(QString::fromStdString(now)) < 0)
            box->addItem(QString::fromStdString(now));
        box->setCurrentIndex(box->findText(QString::fromStdString(now)));
    };
    fill(material_, charts.materials(p.process), p.material);
    fill(consumable_, charts.consumables(p.process, p.material), p.consumable);
    const double wall = partWallMm(job);
    partWall_->setChecked(!p.thickness_mm.has_value());
    thickness_->setValue(p.thickness_mm.value_or(wall));
    thickness_->setEnabled(p.used && p.thickness_mm.has_value());

    const cutcell::ProcessSettings s = cutcell::resolveProcess(p, wall, charts);
    for (std::size_t k = 1; k < cutcell::kCutFigureCount; ++k) {
        const auto f = static_cast<CutFigure>(k);
        const int row = static_cast<int>(k) - 1;
        const bool applies = cutcell::cutFigureApplies(f, p.process);
        figures_->setRowHidden(row, !applies);
        const auto chartValue = s.chart_row.get(f);
        // A dash keeps the column narrow (the page is narrow); the tooltip says what it means.
        figures_->item(row, 1)->setText(chartValue ? number(*chartValue, decimalsOf(f))
                                                   : QStringLiteral("\u2014"));
        figures_->item(row, 1)->setToolTip(chartValue ? QString() : tr("not in the chart"));
        const auto over = p.override.get(f);
        overrideBox_[k]->setChecked(over.has_value());
        // A figure the machine does not take: read-only with the reason (an override in the
        // job stays removable; its issue says why).
        const QString refused = refusal(f);
        overrideBox_[k]->setEnabled(refused.isEmpty() || over.has_value());
        overrideBox_[k]->setToolTip(refused);
        figures_->item(row, 0)->setToolTip(refused);
        const auto used = refused.isEmpty() ? s.effective.get(f) : std::nullopt;
        // A figure neither the chart nor an override gives (or one the machine does not use)
        // shows a dash, not a made-up 0.
        const bool none = !over && !used;
        valueBox_[k]->setSpecialValueText(none ? QStringLiteral("\u2014") : QString());
        valueBox_[k]->setValue(over ? *over : none ? valueBox_[k]->minimum() : *used);
        valueBox_[k]->setEnabled(p.used && over.has_value());
        valueBox_[k]->setToolTip(!refused.isEmpty() ? refused
                                 : over ? tr("Override: saved with the job in place of the "
                                             "chart's figure.")
                                        : tr("The chart's figure; tick Override to set another."));
    }
    figures_->resizeRowsToContents();

    QString text;
    if (!p.used) {
        text = !part_.withoutChart.isEmpty()
                   ? part_.withoutChart
                   : tr("No cut chart: the cut runs at the Cut page's speed, without kerf "
                        "compensation.");
    } else if (!s.ok()) {
        text = tr("Not usable: %1").arg(QString::fromStdString(s.outcome.message));
    } else {
        text = tr("Chart: %1 at %2 mm%3.")
                   .arg(QString::fromStdString(s.chart_name), number(s.thickness_mm, 2),
                        s.thickness_from_part ? tr(" (the part's wall)") : QString());
        text += QLatin1Char(' ') + tr("Source: %1%2.")
                                       .arg(QString::fromStdString(s.chart_source),
                                            s.typical_values ? tr(" (typical values)") : QString());
        if (s.life_pierces || s.life_arc_minutes)
            text += QLatin1Char(' ') +
                    tr("Expected consumable life: %1 pierces, %2 min arc-on.")
                        .arg(s.life_pierces ? QString::number(*s.life_pierces) : tr("unknown"),
                             s.life_arc_minutes ? number(*s.life_arc_minutes, 0) : tr("unknown"));
        if (s.kerfMm() <= 0)
            text += QLatin1Char(' ') + tr("No kerf width: the torch runs on the part's edge "
                                          "(tick Override on Kerf width to compensate).");
    }
    if (const QString problem = installCutChartsInUse(cutcell::defaultDataHome());
        !problem.isEmpty())
        text += QLatin1Char(' ') + tr("The user's cut charts are not used: %1").arg(problem);
    chart_->setText(text);
    refreshing_ = false;
}

} // namespace CutCell::ui
