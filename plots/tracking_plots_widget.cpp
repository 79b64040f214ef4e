#include "plots/tracking_plots_widget.h"

#include "plots/bounded_series.h"

#include <QAction>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPainter>
#include <QSaveFile>
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
    QColor(148, 103, 189), QColor(140, 86, 75),  QColor(227, 119, 194), QColor(127, 127, 127)};
const QColor kCartColours[kCartTraces] = {QColor(220, 50, 47), QColor(40, 160, 60),
                                          QColor(38, 110, 210)};
const char* const kCartNames[kCartTraces] = {"x", "y", "z"};

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
void softReplot(QCustomPlot* p) {
    p->setUpdatesEnabled(false);
    p->replot(QCustomPlot::rpRefreshHint);
    p->setUpdatesEnabled(true);
}

} // namespace

struct TrackingPlotsWidget::Impl {
    TrackingPlotsWidget* self;
    int axes = 6;
    QStringList names;
    BoundedSeries ring{6 + kCartTraces, kDefaultCapacity};
    QCustomPlot* jointPlot = nullptr;
    QCustomPlot* cartPlot = nullptr;
    QAction* pauseAction = nullptr;
    QLabel* status = nullptr;
    QTimer tick;
    std::uint64_t ticks = 0; // timer ticks so far (tests wait for ticks, not for time)
    bool dirty = false;
    bool paused = false;
    bool autoscale = true;
    bool fullResync = true;
    bool viewChanged = false;
    bool hostDriven = false;  // new data is drawn by redrawPending() only // one plot's time range
                              // moved: redraw both at the next tick
    std::uint64_t synced = 0; // ring.appended() at the last sync

    explicit Impl(TrackingPlotsWidget* s) : self(s) {
        for (int i = 0; i < kMaxAxes; ++i)
            names << defaultAxisName(i);
    }

    QCPGraph* graphFor(int trace) const {
        if (trace < axes)
            return trace < jointPlot->graphCount() ? jointPlot->graph(trace) : nullptr;
        const int k = trace - axes;
        return k < cartPlot->graphCount() ? cartPlot->graph(k) : nullptr;
    }
    int traceCount() const { return axes + kCartTraces; }

    QCustomPlot* makePlot(const QString& yLabel) {
        auto* p = new QCustomPlot(self);
        p->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
        p->setNoAntialiasingOnDrag(true);
        p->xAxis->setLabel(QStringLiteral("t (s)"));
        p->yAxis->setLabel(yLabel);
        p->legend->setVisible(true);
        p->legend->setBrush(QColor(255, 255, 255, 210));
        p->legend->setFont(QFont(self->font().family(), 8));
        p->legend->setSelectableParts(QCPLegend::spNone);
        p->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
        p->setMinimumHeight(140);
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
            if (p->legend->visible() && p->legend->selectTest(e->position(), false) >= 0) return;
            autoscale = false;
        };
        QObject::connect(p, &QCustomPlot::mousePress, self, manual);
        QObject::connect(p, &QCustomPlot::mouseWheel, self,
                         [this](QWheelEvent*) { autoscale = false; });
        return p;
    }

    void rebuildGraphs() {
        jointPlot->clearGraphs();
        cartPlot->clearGraphs();
        for (int i = 0; i < axes; ++i) {
            QCPGraph* g = jointPlot->addGraph();
            g->setPen(QPen(kTraceColours[i])); // width 0/1 cosmetic: thick pens are ~50x slower
            g->setName(names.value(i, defaultAxisName(i)));
            g->setAdaptiveSampling(true);
        }
        for (int k = 0; k < kCartTraces; ++k) {
            QCPGraph* g = cartPlot->addGraph();
            g->setPen(QPen(kCartColours[k]));
            g->setName(QString::fromLatin1(kCartNames[k]));
            g->setAdaptiveSampling(true);
        }
        fullResync = true;
        dirty = true;
    }

    void setVisible(int trace, bool visible) {
        QCPGraph* g = graphFor(trace);
        if (!g) return;
        g->setVisible(visible);
        QCustomPlot* p = trace < axes ? jointPlot : cartPlot;
        if (auto* item = p->legend->itemWithPlottable(g))
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
        p->rescaleAxes(true);
        QCPRange y = p->yAxis->range();
        const double pad = std::max(1e-6, y.size() * 0.06);
        p->yAxis->setRange(y.lower - pad, y.upper + pad);
    }

    void refresh() {
        sync();
        if (autoscale) {
            rescale(jointPlot);
            rescale(cartPlot);
        }
        status->setText(
            QStringLiteral("%1 samples, %2 dropped").arg(ring.size()).arg(ring.dropped()));
        dirty = false;
    }

    void onTick(bool fromTimer = false) {
        // Hidden (e.g. another tab): keep the data, draw when shown again.
        if (!self->isVisible()) return;
        if (dirty && !paused && !(fromTimer && hostDriven))
            refresh();
        else if (!viewChanged)
            return;
        softReplot(jointPlot);
        softReplot(cartPlot);
        viewChanged = false;
    }

    QImage render() {
        const int w = std::max(jointPlot->width(), 800);
        const int hj = std::max(jointPlot->height(), 300);
        const int hc = std::max(cartPlot->height(), 300);
        QImage img(w, hj + hc, QImage::Format_ARGB32);
        img.fill(Qt::white);
        QPainter painter(&img);
        painter.drawPixmap(0, 0, jointPlot->toPixmap(w, hj));
        painter.drawPixmap(0, hj, cartPlot->toPixmap(w, hc));
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
    d->pauseAction = bar->addAction(tr("Pause"));
    d->pauseAction->setCheckable(true);
    d->pauseAction->setToolTip(tr("Freeze the plots; data keeps being recorded"));
    connect(d->pauseAction, &QAction::toggled, this, &TrackingPlotsWidget::setPaused);
    QAction* fitAction = bar->addAction(tr("Fit"));
    fitAction->setToolTip(tr("Autoscale both plots and follow the data"));
    connect(fitAction, &QAction::triggered, this, &TrackingPlotsWidget::fit);
    bar->addSeparator();
    connect(bar->addAction(tr("Export PNG...")), &QAction::triggered, this, [this] {
        const QString path =
            QFileDialog::getSaveFileName(this, tr("Export plots as PNG"),
                                         QStringLiteral("tracking.png"), tr("PNG images (*.png)"));
        QString err;
        if (!path.isEmpty() && !exportPng(path, &err))
            QMessageBox::warning(this, tr("Export PNG"), err);
    });
    connect(bar->addAction(tr("Export CSV...")), &QAction::triggered, this, [this] {
        const QString path =
            QFileDialog::getSaveFileName(this, tr("Export errors as CSV"),
                                         QStringLiteral("tracking.csv"), tr("CSV files (*.csv)"));
        QString err;
        if (!path.isEmpty() && !exportCsv(path, &err))
            QMessageBox::warning(this, tr("Export CSV"), err);
    });
    bar->addSeparator();
    d->status = new QLabel(this);
    bar->addWidget(d->status);
    layout->addWidget(bar);

    d->jointPlot = d->makePlot(tr("joint error (deg)"));
    d->cartPlot = d->makePlot(tr("Cartesian error (mm)"));
    // One time axis for both plots.
    connect(d->jointPlot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
            d->cartPlot->xAxis, qOverload<const QCPRange&>(&QCPAxis::setRange));
    connect(d->cartPlot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged),
            d->jointPlot->xAxis, qOverload<const QCPRange&>(&QCPAxis::setRange));
    // The partner plot follows at the next tick (a queued replot would repaint on its own).
    connect(d->jointPlot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
            [this] { d->viewChanged = true; });
    connect(d->cartPlot->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
            [this] { d->viewChanged = true; });
    layout->addWidget(d->jointPlot, 1);
    layout->addWidget(d->cartPlot, 1);
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
        d->jointPlot->graph(i)->setName(d->names[i]);
    d->dirty = true;
}

QStringList TrackingPlotsWidget::axisNames() const {
    return d->names.mid(0, d->axes);
}

void TrackingPlotsWidget::setAxisCount(int n) {
    d->axes = std::clamp(n, 1, kMaxAxes);
    d->ring.setChannels(d->axes + kCartTraces);
    d->synced = 0;
    d->rebuildGraphs();
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

void TrackingPlotsWidget::append(double t_s, const double* jointErrorsDeg, int n,
                                 const double cartErrMm[3]) {
    double row[kMaxAxes + kCartTraces];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int i = 0; i < d->axes; ++i)
        row[i] = (jointErrorsDeg && i < n) ? jointErrorsDeg[i] : nan;
    for (int k = 0; k < kCartTraces; ++k)
        row[d->axes + k] = cartErrMm ? cartErrMm[k] : nan;
    if (!d->ring.empty() && t_s < d->ring.lastTime()) d->fullResync = true;
    d->ring.append(t_s, row, d->axes + kCartTraces);
    d->dirty = true;
}

void TrackingPlotsWidget::clear() {
    d->ring.clear();
    d->synced = 0;
    d->fullResync = true;
    d->dirty = true;
    if (!d->paused) d->onTick();
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
        d->rescale(d->jointPlot);
        d->rescale(d->cartPlot);
        d->jointPlot->replot(QCustomPlot::rpQueuedReplot);
        d->cartPlot->replot(QCustomPlot::rpQueuedReplot);
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
    for (int i = 0; i < d->axes; ++i)
        out += ',' + csvName(d->names[i]).toUtf8() + "_err_deg";
    for (const char* c : kCartNames)
        out += QByteArray(",") + c + "_err_mm";
    out += '\n';
    const int channels = d->axes + kCartTraces;
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
    return d->jointPlot->graphCount() ? d->jointPlot->graph(0)->dataCount() : 0;
}

std::uint64_t TrackingPlotsWidget::timerTicks() const {
    return d->ticks;
}

void TrackingPlotsWidget::redrawPending() {
    d->onTick();
}

void TrackingPlotsWidget::setHostDrivenRedraw(bool on) {
    d->hostDriven = on;
}

double TrackingPlotsWidget::replotNow() {
    d->refresh();
    QElapsedTimer timer;
    timer.start();
    d->jointPlot->replot(QCustomPlot::rpImmediateRefresh);
    d->cartPlot->replot(QCustomPlot::rpImmediateRefresh);
    return static_cast<double>(timer.nsecsElapsed()) / 1e6;
}

} // namespace cutcell::plots
