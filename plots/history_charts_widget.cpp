#include "plots/history_charts_widget.h"

#include <qcustomplot.h>

#include <QHBoxLayout>
#include <QLocale>
#include <QSharedPointer>

#include <algorithm>
#include <cmath>

namespace cutcell::plots {

struct HistoryChartsWidget::Impl {
    QCustomPlot* cycle = nullptr;
    QCustomPlot* pareto = nullptr;
    std::vector<ParetoBar> shown;
    std::vector<double> cumulative;
};

namespace {

QCustomPlot* makePlot(QWidget* parent, const QString& title, const QString& yLabel) {
    auto* p = new QCustomPlot(parent);
    p->setLocale(QLocale::c());
    p->plotLayout()->insertRow(0);
    p->plotLayout()->addElement(0, 0, new QCPTextElement(p, title));
    p->yAxis->setLabel(yLabel);
    p->setMinimumHeight(180);
    return p;
}

QSharedPointer<QCPAxisTickerText> textTicker(const QVector<double>& at,
                                             const QVector<QString>& labels) {
    QSharedPointer<QCPAxisTickerText> t(new QCPAxisTickerText);
    t->addTicks(at, labels);
    return t;
}

} // namespace

HistoryChartsWidget::HistoryChartsWidget(QWidget* parent)
    : QWidget(parent), d_(std::make_unique<Impl>()) {
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(0, 0, 0, 0);
    d_->cycle = makePlot(this, tr("Cycle time per run"), tr("cycle time (s)"));
    d_->pareto = makePlot(this, tr("Alarms (Pareto)"), tr("count"));
    d_->pareto->yAxis2->setVisible(true);
    d_->pareto->yAxis2->setLabel(tr("cumulative (%)"));
    d_->pareto->yAxis2->setRange(0, 105);
    d_->cycle->setObjectName("historyCycleChart");
    d_->pareto->setObjectName("historyParetoChart");
    h->addWidget(d_->cycle, 1);
    h->addWidget(d_->pareto, 1);
}

HistoryChartsWidget::~HistoryChartsWidget() = default;

void HistoryChartsWidget::setCycleTimes(const std::vector<CycleBar>& runs) {
    QCustomPlot* p = d_->cycle;
    p->clearPlottables();
    auto* done = new QCPBars(p->xAxis, p->yAxis);
    auto* stopped = new QCPBars(p->xAxis, p->yAxis);
    done->setName(tr("completed"));
    stopped->setName(tr("stopped short"));
    done->setBrush(QColor(70, 160, 90));
    stopped->setBrush(QColor(210, 120, 40));
    QVector<double> at;
    QVector<QString> labels;
    double top = 0;
    for (size_t i = 0; i < runs.size(); ++i) {
        const double x = static_cast<double>(i + 1);
        (runs[i].completed ? done : stopped)->addData(x, runs[i].seconds);
        top = std::max(top, runs[i].seconds);
        // At most ~12 labels: every k-th run's id.
        const size_t every = std::max<size_t>(1, runs.size() / 12 + 1);
        if (i % every == 0) {
            at << x;
            labels << runs[i].label;
        }
    }
    p->xAxis->setTicker(textTicker(at, labels));
    p->xAxis->setRange(0, static_cast<double>(runs.size()) + 1);
    p->yAxis->setRange(0, top > 0 ? top * 1.1 : 1);
    p->replot();
}

void HistoryChartsWidget::setAlarms(std::vector<ParetoBar> alarms, int keep) {
    std::stable_sort(alarms.begin(), alarms.end(),
                     [](const ParetoBar& a, const ParetoBar& b) { return a.count > b.count; });
    if (keep > 0 && static_cast<int>(alarms.size()) > keep) {
        int rest = 0;
        for (size_t i = static_cast<size_t>(keep - 1); i < alarms.size(); ++i)
            rest += alarms[i].count;
        alarms.resize(static_cast<size_t>(keep - 1));
        alarms.push_back({tr("other"), rest});
    }
    int total = 0;
    for (const ParetoBar& a : alarms)
        total += a.count;
    d_->shown = alarms;
    d_->cumulative.clear();
    QCustomPlot* p = d_->pareto;
    p->clearPlottables();
    auto* bars = new QCPBars(p->xAxis, p->yAxis);
    bars->setBrush(QColor(200, 70, 60));
    auto* line = p->addGraph(p->xAxis, p->yAxis2);
    line->setPen(QPen(QColor(40, 90, 200), 2));
    line->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 5));
    QVector<double> at;
    QVector<QString> labels;
    int sum = 0, top = 0;
    for (size_t i = 0; i < alarms.size(); ++i) {
        const double x = static_cast<double>(i + 1);
        bars->addData(x, alarms[i].count);
        sum += alarms[i].count;
        top = std::max(top, alarms[i].count);
        const double share = total > 0 ? 100.0 * sum / total : 0;
        d_->cumulative.push_back(share);
        line->addData(x, share);
        at << x;
        labels << (alarms[i].label.size() > 18 ? alarms[i].label.left(17) + QChar(0x2026)
                                               : alarms[i].label);
    }
    p->xAxis->setTicker(textTicker(at, labels));
    p->xAxis->setTickLabelRotation(30);
    p->xAxis->setRange(0, static_cast<double>(alarms.size()) + 1);
    // Counts are whole: ticks at whole steps.
    QSharedPointer<QCPAxisTickerFixed> whole(new QCPAxisTickerFixed);
    whole->setTickStep(std::max(1.0, std::ceil(top / 6.0)));
    whole->setScaleStrategy(QCPAxisTickerFixed::ssMultiples);
    p->yAxis->setTicker(whole);
    p->yAxis->setRange(0, top > 0 ? top * 1.15 : 1);
    p->replot();
}

std::vector<ParetoBar> HistoryChartsWidget::paretoShown() const {
    return d_->shown;
}

std::vector<double> HistoryChartsWidget::paretoCumulative() const {
    return d_->cumulative;
}

bool HistoryChartsWidget::savePng(const QString& path, int width, int height) {
    return grab()
        .scaled(width, height, Qt::KeepAspectRatio, Qt::SmoothTransformation)
        .save(path, "PNG");
}

} // namespace cutcell::plots
