#include "plots/xy_figures_widget.h"

#include <qcustomplot.h>

#include <QBoxLayout>
#include <QGridLayout>
#include <QLocale>

#include <algorithm>

#include <cmath>
#include <limits>

namespace cutcell::plots {

struct XyFiguresWidget::Impl {
    QGridLayout* grid = nullptr; // the grid constructor's; null for a row or column
    int columns = 1;             // asked for
    int shownColumns = 0;        // as arranged now
    std::vector<QCustomPlot*> plots;
    std::vector<QCPTextElement*> titles;
    std::vector<int> points;
};

namespace {

constexpr int kPanelMinWidth = 220, kPanelMinHeight = 230;

QCustomPlot* makePanel(QWidget* parent, std::vector<QCPTextElement*>* titles) {
    auto* p = new QCustomPlot(parent);
    p->setLocale(QLocale::c()); // tick labels with a decimal point under any locale
    p->setMinimumSize(kPanelMinWidth, kPanelMinHeight);
    p->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    p->plotLayout()->insertRow(0);
    auto* title = new QCPTextElement(p, QString(), QFont(parent->font().family(), 9, QFont::Bold));
    p->plotLayout()->addElement(0, 0, title);
    p->legend->setVisible(true);
    p->legend->setFont(QFont(parent->font().family(), 8));
    p->legend->setBrush(QColor(255, 255, 255, 200));
    titles->push_back(title);
    return p;
}

} // namespace

XyFiguresWidget::XyFiguresWidget(int panels, Qt::Orientation orientation, QWidget* parent)
    : QWidget(parent), d(std::make_unique<Impl>()) {
    auto* row = new QBoxLayout(
        orientation == Qt::Horizontal ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom, this);
    row->setContentsMargins(0, 0, 0, 0);
    for (int i = 0; i < panels; ++i) {
        QCustomPlot* p = makePanel(this, &d->titles);
        row->addWidget(p, 1);
        d->plots.push_back(p);
        d->points.push_back(0);
    }
}

XyFiguresWidget::XyFiguresWidget(int panels, int columns, QWidget* parent)
    : QWidget(parent), d(std::make_unique<Impl>()) {
    d->grid = new QGridLayout(this);
    d->grid->setContentsMargins(0, 0, 0, 0);
    d->columns = std::max(1, columns);
    for (int i = 0; i < panels; ++i) {
        d->plots.push_back(makePanel(this, &d->titles));
        d->points.push_back(0);
    }
    // One panel's width at least (the layout's minimum height stays: rows grow as columns go).
    setMinimumWidth(kPanelMinWidth);
    arrange(d->columns);
}

void XyFiguresWidget::arrange(int columns) {
    if (!d->grid || columns == d->shownColumns) return;
    d->shownColumns = columns;
    for (QCustomPlot* p : d->plots)
        d->grid->removeWidget(p);
    const int panels = static_cast<int>(d->plots.size());
    for (int i = 0; i < panels; ++i) {
        // The last panel spans what is left of its row.
        const int span = i == panels - 1 ? columns - i % columns : 1;
        d->grid->addWidget(d->plots[static_cast<size_t>(i)], i / columns, i % columns, 1, span);
    }
    for (int c = 0; c < d->columns; ++c)
        d->grid->setColumnStretch(c, c < columns ? 1 : 0);
}

void XyFiguresWidget::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    const int spacing = d->grid ? std::max(0, d->grid->spacing()) : 0;
    arrange(std::clamp((width() + spacing) / (kPanelMinWidth + spacing), 1, d->columns));
}

XyFiguresWidget::~XyFiguresWidget() = default;

int XyFiguresWidget::panelCount() const {
    return static_cast<int>(d->plots.size());
}

void XyFiguresWidget::setPanel(int panel, const QString& title, const QString& xLabel,
                               const QString& yLabel) {
    QCustomPlot* p = d->plots.at(static_cast<size_t>(panel));
    d->titles[static_cast<size_t>(panel)]->setText(title);
    p->xAxis->setLabel(xLabel);
    p->yAxis->setLabel(yLabel);
    p->replot(QCustomPlot::rpQueuedReplot);
}

void XyFiguresWidget::setCurves(int panel, const std::vector<XyCurve>& curves) {
    QCustomPlot* p = d->plots.at(static_cast<size_t>(panel));
    p->clearPlottables();
    int points = 0;
    for (const XyCurve& c : curves) {
        auto* curve = new QCPCurve(p->xAxis, p->yAxis);
        curve->setName(c.name);
        QPen pen(c.colour, 1.6);
        if (c.dashed) pen.setStyle(Qt::DashLine);
        curve->setPen(pen);
        QVector<double> t, x, y;
        const int n = static_cast<int>(std::min(c.x.size(), c.y.size()));
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (int i = 0; i < n; ++i) {
            const bool ok = std::isfinite(c.x[i]) && std::isfinite(c.y[i]);
            t.push_back(i);
            x.push_back(ok ? c.x[i] : nan); // QCustomPlot leaves a gap at NaN
            y.push_back(ok ? c.y[i] : nan);
            points += ok ? 1 : 0;
        }
        curve->setData(t, x, y, true);
    }
    d->points[static_cast<size_t>(panel)] = points;
    p->rescaleAxes();
    p->replot(QCustomPlot::rpQueuedReplot);
}

void XyFiguresWidget::setLegendAlignment(int panel, Qt::Alignment alignment) {
    QCustomPlot* p = d->plots.at(static_cast<size_t>(panel));
    p->axisRect()->insetLayout()->setInsetAlignment(0, alignment);
    p->replot(QCustomPlot::rpQueuedReplot);
}

void XyFiguresWidget::setLegendColumns(int panel, int columns) {
    QCustomPlot* p = d->plots.at(static_cast<size_t>(panel));
    p->legend->setVisible(columns > 0);
    if (columns > 0) {
        p->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
        p->legend->setWrap(columns);
        p->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    }
    p->replot(QCustomPlot::rpQueuedReplot);
}

int XyFiguresWidget::curveCount(int panel) const {
    return d->plots.at(static_cast<size_t>(panel))->plottableCount();
}

int XyFiguresWidget::pointCount(int panel) const {
    return d->points.at(static_cast<size_t>(panel));
}

} // namespace cutcell::plots
