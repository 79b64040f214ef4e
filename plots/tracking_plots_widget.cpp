#include "plots/tracking_plots_widget.h"

#include <QHash>

#include "plots/bounded_series.h"

#include <QAction>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPainter>
#include <QSaveFile>
#include <QSignalBlocker>
#include <QTabBar>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace cutcell::plots {

namespace {

constexpr int kCartTraces = 3;
constexpr int kTickMs = 33; // ~30 Hz

const QColor kTraceColours[TrackingPlotsWidget::kMaxAxes] = {
    QColor(31, 119, 180),  QColor(255, 127, 14), QColor(44, 160, 44),   QColor(214, 39, 40),
    QColor(148, 103, 189), QColor(140, 86, 75),  QColor(227, 119, 194), QColor(127, 127, 127),
    QColor(188, 189, 34),  QColor(23, 190, 207), QColor(0, 0, 0),       QColor(255, 152, 150)};
const QColor kCartColours[kCartTraces] = {QColor(220, 50, 47), QColor(40, 160, 60),
                                          QColor(38, 110, 210)};

QString defaultAxisName(int i) {
    return i == 0 ? QStringLiteral("A0 chuck") : QStringLiteral("J%1").arg(i);
}

QString csvName(QString s) {
    for (QChar& c : s)
        if (!c.isLetterOrNumber()) c = QLatin1Char('_');
    return s;
}

// QCustomPlot 2.1's replot() ends in a synchronous repaint(). With a QOpenGLWidget (the 3D
// view) in the window, every repaint is a full-window GL composition (~10-40 ms on llvmpipe),
// one per plot per tick. Draw into the plot's buffers with updates off (repaint() is then a
// no-op); re-enabling schedules a soft update() that joins the window's next composition.
// The y ticks from the plot's height: about kTickSpacingPx between labels, so they never
// overlap on a short plot (1280x720 leaves ~60 px of axis), and at least two. The ticker meets
// the count (tssMeetTickCount) instead of rounding the step to 1-2-5, which could leave one
// tick in view or pack five into 60 px.
constexpr int kTickSpacingPx = 24;
// The narrowest y range a plot shows, as a half span in the axis's unit (deg or mm) or, away
// from 0, relative to the value: an error that stays 0 is drawn as a line in the middle. Far
// below any error worth seeing: the simulated robot's are about 1e-5 deg and fill the plot.
constexpr double kMinHalfSpan = 1e-6;
void fitTicks(QCustomPlot* p) {
    const int h = p->axisRect()->height() > 0 ? p->axisRect()->height() : p->height() - 60;
    p->yAxis->ticker()->setTickCount(std::clamp(h / kTickSpacingPx, 2, 8));
}

void softReplot(QCustomPlot* p) {
    fitTicks(p);
    p->setUpdatesEnabled(false);
    p->replot(QCustomPlot::rpRefreshHint);
    p->setUpdatesEnabled(true);
}

} // namespace

struct TrackingPlotsWidget::Impl {
    TrackingPlotsWidget* self;
    QVBoxLayout* layout = nullptr;
    int axes = 6;
    QStringList names;                    // kMaxAxes axis names
    QStringList units;                    // kMaxAxes axis units
    QHash<QString, QString> signalTitles; // unit -> title of a plot of signals, not errors
    QStringList tipNames{"x", "y", "z"};
    QString tipTitle; // set in the constructor (translated)
    BoundedSeries ring{6 + kCartTraces, kDefaultCapacity};
    std::vector<QCustomPlot*> plots;     // pool; plots[0..shown) are in use, the rest hidden
    std::vector<QCPTextElement*> titles; // the title row of each plot in the pool
    std::vector<QCPLayoutGrid*> heads;   // each plot's head: its title over its legend
    QStringList titleTexts;              // what each title says (blank in tabs: the tab says it)
    QTabBar* tabs = nullptr;             // one plot at a time when the widget is short
    QAction* tabsAction = nullptr;       // the tabs' place in the toolbar
    bool tabbed = false;
    int shown = 0;
    std::vector<QCPGraph*> graphs; // one per trace: axes, then tip traces
    std::vector<int> plotOf;       // the plot index of each trace
    QAction* pauseAction = nullptr;
    QLabel* status = nullptr;
    QTimer tick;
    std::uint64_t ticks = 0; // timer ticks so far (tests wait for ticks, not for time)
    bool dirty = false;
    bool paused = false;
    bool autoscale = true;
    bool legendShown = true;
    TrackingPlotsWidget::SavePathAsker
        askSavePath; // the toolbar's Legend toggle, for plots made later too
    bool fullResync = true;
    bool viewChanged = false; // one plot's time range moved: redraw all at the next tick
    bool hostDriven = false;  // new data is drawn by redrawPending() only
    std::uint64_t synced = 0; // ring.appended() at the last sync

    explicit Impl(TrackingPlotsWidget* s) : self(s) {
        for (int i = 0; i < kMaxAxes; ++i) {
            names << defaultAxisName(i);
            units << QStringLiteral("deg");
        }
    }

    int tipCount() const { return static_cast<int>(tipNames.size()); }
    int traceCount() const { return axes + tipCount(); }
    QCPGraph* graphFor(int trace) const {
        return trace >= 0 && trace < static_cast<int>(graphs.size()) ? graphs[size_t(trace)]
                                                                     : nullptr;
    }
    QCustomPlot* plotFor(int trace) const { return plots[size_t(plotOf[size_t(trace)])]; }

    QCustomPlot* makePlot() {
        auto* p = new QCustomPlot(self);
        p->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
        p->setNoAntialiasingOnDrag(true);
        p->xAxis->setLabel(QStringLiteral("t (s)"));
        // Three significant digits ("0.000432", "1.5e-05"): long labels squeezed the plot.
        p->yAxis->setNumberFormat(QStringLiteral("g"));
        p->yAxis->setNumberPrecision(3);
        p->yAxis->ticker()->setTickStepStrategy(QCPAxisTicker::tssMeetTickCount); // fitTicks()
        // The plot's name sits in a row above the axes: a vertical y label ("Cartesian error
        // (mm)") was cut when the plot was shorter than the text. usePlot() sets its text.
        auto* head = new QCPLayoutGrid;
        p->plotLayout()->insertRow(0);
        p->plotLayout()->setRowStretchFactor(0, 0.001);
        p->plotLayout()->addElement(0, 0, head);
        auto* title =
            new QCPTextElement(p, QString(), QFont(self->font().family(), 9, QFont::Bold));
        title->setObjectName(QStringLiteral("plotTitle"));
        head->addElement(0, 0, title);
        // The legend in a row of its own under the title, outside the axes: inside, it covered
        // the newest data and the y labels; beside the title both were cut at 1280x720.
        p->axisRect()->insetLayout()->take(p->legend);
        p->axisRect()->insetLayout()->simplify();
        head->addElement(1, 0, p->legend);
        head->setRowSpacing(0);
        p->legend->setVisible(legendShown);
        p->legend->setBrush(QColor(255, 255, 255, 200));
        p->legend->setFont(QFont(self->font().family(), 8));
        p->legend->setTextColor(Qt::black);
        p->legend->setSelectableParts(QCPLegend::spNone);
        p->legend->setIconSize(18, 8);
        // Entries in rows as wide as the plot allows (arrange(): a column of six outgrew a short
        // plot).
        p->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
        p->legend->setWrap(6);
        p->legend->setRowSpacing(0);
        p->legend->setColumnSpacing(6);
        head->setColumnStretchFactor(0, 1);
        head->setMargins(QMargins(0, 0, 0, 0));
        p->setMinimumHeight(90); // short screens: the 3D view needs the height more
        QObject::connect(p, &QCustomPlot::legendClick, self,
                         [this, p](QCPLegend*, QCPAbstractLegendItem* item, QMouseEvent*) {
                             auto* pli = qobject_cast<QCPPlottableLegendItem*>(item);
                             if (!pli) return;
                             for (int t = 0; t < traceCount(); ++t)
                                 if (graphFor(t) == pli->plottable())
                                     setVisible(t, !pli->plottable()->visible());
                             p->replot(QCustomPlot::rpQueuedReplot);
                         });
        // Zooming or panning by hand means the user wants that range: stop autoscaling.
        const auto manual = [this, p](QMouseEvent* e) {
            if (p->legend->visible() && p->legend->outerRect().contains(e->position().toPoint()))
                return;
            autoscale = false;
        };
        QObject::connect(p, &QCustomPlot::mousePress, self, manual);
        QObject::connect(p, &QCustomPlot::mouseWheel, self,
                         [this](QWheelEvent*) { autoscale = false; });
        // One time axis for every plot; the others follow at the next tick (a queued replot
        // would repaint on its own).
        for (QCustomPlot* other : plots) {
            QObject::connect(p->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
                             other->xAxis, qOverload<const QCPRange&>(&QCPAxis::setRange));
            QObject::connect(other->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
                             p->xAxis, qOverload<const QCPRange&>(&QCPAxis::setRange));
        }
        QObject::connect(p->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), self,
                         [this] { viewChanged = true; });
        layout->addWidget(p, 1);
        plots.push_back(p);
        titles.push_back(title);
        heads.push_back(head);
        titleTexts << QString();
        return p;
    }

    QCustomPlot* usePlot(const QString& yLabel) {
        if (shown == static_cast<int>(plots.size())) makePlot();
        titleTexts[shown] = yLabel;
        return plots[size_t(shown++)];
    }

    // One plot per axis unit (in order of first appearance), then the tip plot.
    void rebuildGraphs() {
        for (QCustomPlot* p : plots)
            p->clearGraphs();
        shown = 0;
        graphs.assign(size_t(traceCount()), nullptr);
        plotOf.assign(size_t(traceCount()), 0);
        QStringList unitOrder;
        for (int i = 0; i < axes; ++i)
            if (!unitOrder.contains(units[i])) unitOrder << units[i];
        for (const QString& unit : unitOrder) {
            const int plot = shown;
            QCustomPlot* p =
                usePlot(signalTitles.value(unit, TrackingPlotsWidget::tr("error (%1)").arg(unit)));
            for (int i = 0; i < axes; ++i) {
                if (units[i] != unit) continue;
                QCPGraph* g = p->addGraph();
                g->setPen(QPen(kTraceColours[i])); // width 0/1 cosmetic: thick pens are ~50x slower
                g->setName(names[i]);
                g->setAdaptiveSampling(true);
                graphs[size_t(i)] = g;
                plotOf[size_t(i)] = plot;
            }
        }
        if (tipCount() > 0) {
            const int plot = shown;
            QCustomPlot* p = usePlot(tipTitle);
            for (int k = 0; k < tipCount(); ++k) {
                QCPGraph* g = p->addGraph();
                g->setPen(QPen(kCartColours[k % kCartTraces]));
                g->setName(tipNames[k]);
                g->setAdaptiveSampling(true);
                graphs[size_t(axes + k)] = g;
                plotOf[size_t(axes + k)] = plot;
            }
        }
        arrange();
        fullResync = true;
        dirty = true;
    }

    // The title row in the plot's head (stacked) or not (tabs: the tab names the plot; an empty
    // title still took a text line's height).
    void showTitle(int plot, bool on) {
        QCPTextElement* title = titles[size_t(plot)];
        auto* head = heads[size_t(plot)];
        title->setText(titleTexts[plot]);
        const bool there = title->layout() == head;
        if (on == there) return;
        if (on) {
            head->insertRow(0);
            head->addElement(0, 0, title);
        } else {
            head->take(title);
            head->simplify();
        }
    }

    // Entries per legend row: all in one row when their names fit the plot's width (a second
    // row costs the data ~14 px), else as many as fit.
    int legendWrap(QCustomPlot* p) const {
        const int width = std::max(100, self->width() - 24);
        int used = 0, fit = 0;
        for (int i = 0; i < p->legend->itemCount(); ++i) {
            // The legend's grid keeps empty cells after its graphs are rebuilt (until it is laid
            // out again): item() is null there.
            const QCPAbstractLegendItem* item = p->legend->item(i);
            if (!item) continue;
            used += item->minimumOuterSizeHint().width() + p->legend->columnSpacing();
            if (used > width) break;
            ++fit;
        }
        return std::max(1, fit);
    }

    // Stacked while each plot gets kMinStackedPlotPx, else one plot at a time under tabs named
    // by the plots' titles (1280x720 left ~95 px a plot: an axis of 57 px, nothing readable).
    static constexpr int kMinStackedPlotPx = 170;
    void arrange() {
        const int bar = tabs->sizeHint().height();
        const bool wantTabs = shown > 1 && self->height() < shown * kMinStackedPlotPx + bar;
        const bool tabsChanged = wantTabs != tabbed || tabs->count() != (wantTabs ? shown : 0);
        tabbed = wantTabs;
        if (tabsChanged) {
            const QSignalBlocker quiet(tabs);
            const int current = std::max(0, tabs->currentIndex());
            while (tabs->count() > 0)
                tabs->removeTab(0);
            if (tabbed)
                for (int i = 0; i < shown; ++i)
                    tabs->addTab(titleTexts[i]);
            tabs->setCurrentIndex(std::min(current, std::max(0, shown - 1)));
        }
        if (tabsAction) tabsAction->setVisible(tabbed);
        for (int i = 0; i < static_cast<int>(plots.size()); ++i) {
            QCustomPlot* p = plots[size_t(i)];
            showTitle(i, !tabbed);
            // setWrap alone leaves the entries in their cells: refill them (the wrap computed
            // before the first show, at 100 px, kept a saw's three entries one per row).
            if (const int wrap = legendWrap(p); wrap != p->legend->wrap()) {
                p->legend->setWrap(wrap);
                p->legend->setFillOrder(p->legend->fillOrder(), true);
            }
            p->setVisible(i < shown && (!tabbed || i == tabs->currentIndex()));
        }
        viewChanged = true;
    }

    void resetChannels() {
        ring.setChannels(traceCount());
        synced = 0;
        rebuildGraphs();
    }

    void setVisible(int trace, bool visible) {
        QCPGraph* g = graphFor(trace);
        if (!g) return;
        g->setVisible(visible);
        if (auto* item = plotFor(trace)->legend->itemWithPlottable(g))
            item->setTextColor(visible ? Qt::black : QColor(170, 170, 170));
        dirty = true;
    }

    // Moves what the ring holds and the plots do not into the plots.
    void sync() {
        const std::uint64_t fresh = ring.appended() - synced;
        const int n = ring.size();
        const bool full = fullResync || fresh > static_cast<std::uint64_t>(n);
        const int from = full ? 0 : n - static_cast<int>(fresh);
        QVector<QCPGraphData> pts(n - from);
        for (int t = 0; t < traceCount(); ++t) {
            QCPGraph* g = graphFor(t);
            for (int i = from; i < n; ++i)
                pts[i - from] = QCPGraphData(ring.time(i), ring.value(i, t));
            if (full)
                g->data()->set(pts, false);
            else
                g->data()->add(pts, true);
            if (ring.dropped() > 0 && n > 0) g->data()->removeBefore(ring.time(0));
        }
        synced = ring.appended();
        fullResync = false;
    }

    void rescale(QCustomPlot* p) {
        p->rescaleAxes(true); // x from the data
        // y from the data alone, never from the range shown: for a flat trace (an error that
        // stays 0) QCPAxis::rescale keeps the current span, and the pad added to it grew the
        // range 12 % on every redraw, to +-1e15 within a minute.
        bool found = false;
        QCPRange y;
        for (int g = 0; g < p->graphCount(); ++g) {
            if (!p->graph(g)->visible()) continue;
            bool ok = false;
            const QCPRange r = p->graph(g)->getValueRange(ok, QCP::sdBoth, p->xAxis->range());
            if (!ok) continue;
            y = found ? QCPRange(std::min(y.lower, r.lower), std::max(y.upper, r.upper)) : r;
            found = true;
        }
        if (!found) return;
        const double centre = y.center();
        const double half =
            std::max(0.5 * y.size(), kMinHalfSpan * std::max(1.0, std::fabs(centre)));
        const double halfShown = half * 1.12; // 6 % of the data's span as a margin on each side
        p->yAxis->setRange(centre - halfShown, centre + halfShown);
    }
    void rescaleAll() {
        for (int i = 0; i < shown; ++i)
            rescale(plots[size_t(i)]);
    }

    void refresh() {
        sync();
        if (autoscale) rescaleAll();
        status->setText(tr("%1 samples, %2 dropped").arg(ring.size()).arg(ring.dropped()));
        dirty = false;
    }

    void onTick(bool fromTimer = false) {
        // Hidden (e.g. another tab): keep the data, draw when shown again.
        if (!self->isVisible()) return;
        if (dirty && !paused && !(fromTimer && hostDriven))
            refresh();
        else if (!viewChanged)
            return;
        for (int i = 0; i < shown; ++i)
            softReplot(plots[size_t(i)]);
        viewChanged = false;
    }

    QImage render() {
        const int w = std::max(plots[0]->width(), 800);
        std::vector<int> heights;
        int total = 0;
        for (int i = 0; i < shown; ++i) {
            heights.push_back(std::max(plots[size_t(i)]->height(), 300));
            total += heights.back();
        }
        QImage img(w, std::max(total, 1), QImage::Format_ARGB32);
        img.fill(Qt::white);
        QPainter painter(&img);
        int y = 0;
        for (int i = 0; i < shown; ++i) {
            painter.drawPixmap(0, y, plots[size_t(i)]->toPixmap(w, heights[size_t(i)]));
            y += heights[size_t(i)];
        }
        return img;
    }
};

TrackingPlotsWidget::TrackingPlotsWidget(QWidget* parent)
    : QWidget(parent), d(std::make_unique<Impl>(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    auto* bar = new QToolBar(this);
    bar->setIconSize(QSize(16, 16));
    d->tabs = new QTabBar(this);
    d->tabs->setObjectName(QStringLiteral("plotTabs"));
    d->tabs->setDrawBase(false);
    d->tabs->setExpanding(false);
    d->tabs->setUsesScrollButtons(false); // both tabs whole; the toolbar moves exports out first
    connect(d->tabs, &QTabBar::currentChanged, this, [this] {
        d->arrange();
        d->onTick();
    });
    d->pauseAction = bar->addAction(tr("Pause"));
    d->pauseAction->setCheckable(true);
    d->pauseAction->setToolTip(tr("Freeze the plots; data keeps being recorded"));
    connect(d->pauseAction, &QAction::toggled, this, &TrackingPlotsWidget::setPaused);
    QAction* fitAction = bar->addAction(tr("Fit"));
    fitAction->setToolTip(tr("Autoscale both plots and follow the data"));
    connect(fitAction, &QAction::triggered, this, &TrackingPlotsWidget::fit);
    QAction* legendAction = bar->addAction(tr("Legend"));
    legendAction->setObjectName(QStringLiteral("legendAction"));
    legendAction->setCheckable(true);
    legendAction->setChecked(true);
    legendAction->setToolTip(tr("Show or hide the trace names above the plots"));
    connect(legendAction, &QAction::toggled, this, [this](bool on) {
        d->legendShown = on;
        for (QCustomPlot* p : d->plots) {
            p->legend->setVisible(on);
            p->replot(QCustomPlot::rpQueuedReplot);
        }
    });
    // The plot tabs share the toolbar's row (a row of their own took the data's height), before
    // the exports: a narrow toolbar moves its last entries into its overflow menu first.
    bar->addSeparator();
    d->tabsAction = bar->addWidget(d->tabs);
    bar->addSeparator();
    const auto askPath = [this](const QString& title, const QString& tail, const QString& filter) {
        if (d->askSavePath) return d->askSavePath(title, tail, filter);
        return QFileDialog::getSaveFileName(this, title, QStringLiteral("tracking") + tail, filter);
    };
    connect(bar->addAction(tr("Export PNG...")), &QAction::triggered, this, [this, askPath] {
        const QString path = askPath(tr("Export plots as PNG"), QStringLiteral("_plots.png"),
                                     tr("PNG images (*.png)"));
        QString err;
        if (!path.isEmpty() && !exportPng(path, &err))
            QMessageBox::warning(this, tr("Export PNG"), err);
    });
    connect(bar->addAction(tr("Export CSV...")), &QAction::triggered, this, [this, askPath] {
        const QString path = askPath(tr("Export errors as CSV"), QStringLiteral("_tracking.csv"),
                                     tr("CSV files (*.csv)"));
        QString err;
        if (!path.isEmpty() && !exportCsv(path, &err))
            QMessageBox::warning(this, tr("Export CSV"), err);
    });
    bar->addSeparator();
    d->status = new QLabel(this);
    bar->addWidget(d->status);
    layout->addWidget(bar);

    d->layout = layout;
    d->tipTitle = tr("Cartesian error (mm)");
    d->rebuildGraphs();
    d->refresh();

    d->tick.setInterval(kTickMs);
    connect(&d->tick, &QTimer::timeout, this, [this] {
        d->onTick(true);
        ++d->ticks;
    });
    d->tick.start();
}

TrackingPlotsWidget::~TrackingPlotsWidget() = default;

void TrackingPlotsWidget::setAxisNames(const QStringList& names) {
    for (int i = 0; i < std::min<int>(static_cast<int>(names.size()), kMaxAxes); ++i)
        d->names[i] = names[i];
    for (int i = 0; i < d->axes; ++i)
        d->graphs[size_t(i)]->setName(d->names[i]);
    d->dirty = true;
}

void TrackingPlotsWidget::setSignalPlot(const QString& unit, const QString& title) {
    if (title.isEmpty())
        d->signalTitles.remove(unit);
    else
        d->signalTitles.insert(unit, title);
}

void TrackingPlotsWidget::setAxes(const QStringList& names, const QStringList& units) {
    d->axes = std::clamp(static_cast<int>(names.size()), 1, kMaxAxes);
    for (int i = 0; i < d->axes; ++i) {
        d->names[i] = names.value(i, defaultAxisName(i));
        d->units[i] = units.value(i, QStringLiteral("deg"));
    }
    d->resetChannels();
}

QStringList TrackingPlotsWidget::axisUnits() const {
    return d->units.mid(0, d->axes);
}

void TrackingPlotsWidget::setTipTraces(const QStringList& names, const QString& title) {
    d->tipNames = names.mid(0, kCartTraces);
    d->tipTitle = title;
    d->resetChannels();
}

QStringList TrackingPlotsWidget::tipTraceNames() const {
    return d->tipNames;
}

QStringList TrackingPlotsWidget::plotTitles() const {
    QStringList titles;
    for (int i = 0; i < d->shown; ++i)
        titles << d->titleTexts[i];
    return titles;
}

QStringList TrackingPlotsWidget::plotTraceNames(int plot) const {
    QStringList traces;
    if (plot < 0 || plot >= d->shown) return traces;
    const QCustomPlot* p = d->plots[size_t(plot)];
    for (int g = 0; g < p->graphCount(); ++g)
        traces << p->graph(g)->name();
    return traces;
}

QStringList TrackingPlotsWidget::axisNames() const {
    return d->names.mid(0, d->axes);
}

void TrackingPlotsWidget::setAxisCount(int n) {
    d->axes = std::clamp(n, 1, kMaxAxes);
    d->resetChannels();
}

int TrackingPlotsWidget::axisCount() const {
    return d->axes;
}

void TrackingPlotsWidget::setCapacity(int samples) {
    d->ring.setCapacity(samples);
    d->synced = 0;
    d->fullResync = true;
    d->dirty = true;
}

int TrackingPlotsWidget::capacity() const {
    return d->ring.capacity();
}

void TrackingPlotsWidget::append(double t_s, const double* axisErrors, int n,
                                 const double* tipErrMm) {
    double row[kMaxAxes + kCartTraces];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int i = 0; i < d->axes; ++i)
        row[i] = (axisErrors && i < n) ? axisErrors[i] : nan;
    for (int k = 0; k < d->tipCount(); ++k)
        row[d->axes + k] = tipErrMm ? tipErrMm[k] : nan;
    if (!d->ring.empty() && t_s < d->ring.lastTime()) d->fullResync = true;
    d->ring.append(t_s, row, d->traceCount());
    d->dirty = true;
}

void TrackingPlotsWidget::clear() {
    d->ring.clear();
    d->autoscale = true; // a new run or job: the ranges follow its data, not the last zoom
    d->synced = 0;
    d->fullResync = true;
    d->dirty = true;
    if (!d->paused) d->onTick();
}

void TrackingPlotsWidget::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    d->arrange();
}

void TrackingPlotsWidget::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    d->onTick(); // catch up with what arrived while hidden
}

void TrackingPlotsWidget::setPaused(bool paused) {
    if (d->paused == paused) return;
    d->paused = paused;
    const QSignalBlocker block(d->pauseAction);
    d->pauseAction->setChecked(paused);
    if (!paused) d->onTick();
    emit pausedChanged(paused);
}

bool TrackingPlotsWidget::isPaused() const {
    return d->paused;
}

void TrackingPlotsWidget::fit() {
    d->autoscale = true;
    d->dirty = true;
    if (d->paused) { // a paused view still fits what it shows
        d->rescaleAll();
        for (int i = 0; i < d->shown; ++i)
            d->plots[size_t(i)]->replot(QCustomPlot::rpQueuedReplot);
    } else {
        d->onTick();
    }
}

bool TrackingPlotsWidget::autoscale() const {
    return d->autoscale;
}

void TrackingPlotsWidget::setTraceVisible(int trace, bool visible) {
    d->setVisible(trace, visible);
}

bool TrackingPlotsWidget::traceVisible(int trace) const {
    const QCPGraph* g = d->graphFor(trace);
    return g && g->visible();
}

bool TrackingPlotsWidget::exportPng(const QString& path, QString* error) {
    if (!d->paused) d->refresh(); // export what the user sees (a paused view stays as shown)
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || !d->render().save(&file, "PNG") || !file.commit()) {
        if (error) *error = tr("Cannot write the PNG file '%1': %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

bool TrackingPlotsWidget::exportCsv(const QString& path, QString* error) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error) *error = tr("Cannot write the CSV file '%1': %2").arg(path, file.errorString());
        return false;
    }
    QByteArray out = "t_s";
    // Each column names its unit: an axis's own (deg or mm), the tip's mm.
    for (int i = 0; i < d->axes; ++i)
        out += ',' + csvName(d->names[i]).toUtf8() +
               (d->signalTitles.contains(d->units[i]) ? "_" : "_err_") +
               csvName(d->units[i]).toUtf8();
    for (const QString& c : d->tipNames)
        out += ',' + csvName(c).toUtf8() + "_err_mm";
    out += '\n';
    const int channels = d->traceCount();
    for (int i = 0; i < d->ring.size(); ++i) {
        out += QByteArray::number(d->ring.time(i), 'g', 10);
        for (int c = 0; c < channels; ++c) {
            out += ',';
            const double v = d->ring.value(i, c);
            if (!std::isnan(v)) out += QByteArray::number(v, 'g', 10);
        }
        out += '\n';
        if (out.size() > (1 << 20)) { // write in chunks; a 60 000-row file stays small in memory
            file.write(out);
            out.clear();
        }
    }
    file.write(out);
    if (!file.commit()) {
        if (error) *error = tr("Cannot write the CSV file '%1': %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

int TrackingPlotsWidget::sampleCount() const {
    return d->ring.size();
}

std::uint64_t TrackingPlotsWidget::droppedCount() const {
    return d->ring.dropped();
}

int TrackingPlotsWidget::plottedPointCount() const {
    return d->graphs.empty() ? 0 : d->graphs[0]->dataCount();
}

std::uint64_t TrackingPlotsWidget::timerTicks() const {
    return d->ticks;
}

void TrackingPlotsWidget::redrawPending() {
    d->onTick();
}

void TrackingPlotsWidget::setSavePathAsker(SavePathAsker ask) {
    d->askSavePath = std::move(ask);
}

void TrackingPlotsWidget::setHostDrivenRedraw(bool on) {
    d->hostDriven = on;
}

double TrackingPlotsWidget::replotNow() {
    d->refresh();
    QElapsedTimer timer;
    timer.start();
    for (int i = 0; i < d->shown; ++i) {
        fitTicks(d->plots[size_t(i)]);
        d->plots[size_t(i)]->replot(QCustomPlot::rpImmediateRefresh);
    }
    return static_cast<double>(timer.nsecsElapsed()) / 1e6;
}

} // namespace cutcell::plots
