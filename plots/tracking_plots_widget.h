#pragma once
// Live tracking-error plots: the axis errors, one plot per unit (e.g. rotary axes in deg, linear
// axes in mm: never millimetres on a degree scale), above the tool tip's error (mm; by default
// Cartesian x/y/z, or the machine's own traces, or none), with a small toolbar (Pause, Fit,
// Export PNG..., Export CSV...). The machine's axis names and units come from its MachineUi.
//
// Data path: append() only stores into a bounded ring (no replot, no allocation); one 30 Hz
// QTimer moves what is new into the plots and asks for a queued replot, and only when
// something changed and the widget is visible. Paused: data keeps arriving into the ring, the view
// stays frozen. Mouse: drag pans, wheel zooms (either turns autoscale off; Fit turns it back on);
// clicking a legend entry hides or shows its trace. A short widget (under ~170 px a plot) shows
// one plot at a time under tabs named by the plots' titles; the legend sits under the title,
// outside the data, and can be hidden (Legend). QCustomPlot is an implementation detail
// (pimpl).
//
// Threading: GUI thread only, like every QWidget. Times must not decrease between clear()s;
// a sample older than the last one restarts the plots from the ring's content.
#include <QStringList>
#include <QWidget>

#include <cstdint>
#include <functional>
#include <memory>

namespace cutcell::plots {

class TrackingPlotsWidget : public QWidget {
    Q_OBJECT
  public:
    static constexpr int kMaxAxes = 12;            // traces: up to 8 axes and a process's signals
    static constexpr int kDefaultCapacity = 60000; // samples kept per trace (60 s at 1 kHz)

    explicit TrackingPlotsWidget(QWidget* parent = nullptr);
    ~TrackingPlotsWidget() override;

    // The axis traces with their units ("deg", "mm", ...): one plot per unit, in order of first
    // appearance. Clears the data.
    void setAxes(const QStringList& names, const QStringList& units);
    QStringList axisUnits() const;
    // A plot whose traces are not errors (a process's signals: the arc voltage, the torch
    // height): its title instead of "error (unit)", and its CSV columns without "_err". Kept
    // across setAxes(); an empty title removes it.
    void setSignalPlot(const QString& unit, const QString& title);
    // The tip error traces (unit mm) and their plot's title; no names: no tip plot. Default
    // {"x", "y", "z"}, "Cartesian error (mm)". Clears the data.
    void setTipTraces(const QStringList& names, const QString& title);
    QStringList tipTraceNames() const;
    // The y-axis titles of the plots shown, top to bottom, and the trace names of each.
    QStringList plotTitles() const;
    QStringList plotTraceNames(int plot) const;

    // Names of the axis traces, e.g. {"A0 chuck", "J1", ...}; shorter lists keep defaults.
    void setAxisNames(const QStringList& names);
    QStringList axisNames() const;
    // Number of axis traces (1..kMaxAxes), new ones in deg; clears the data.
    void setAxisCount(int n);
    int axisCount() const;
    // Ring capacity in samples; clears the data.
    void setCapacity(int samples);
    int capacity() const;

    // Cheap: copies into the ring. axisErrors has n values, each in its axis's unit (extra ones
    // are ignored, missing ones are NaN); tipErrMm has one value per tip trace or is null (NaN).
    void append(double t_s, const double* axisErrors, int n, const double* tipErrMm);
    void clear();

    void setPaused(bool paused);
    bool isPaused() const;
    // Autoscale both plots and follow the data again.
    void fit();
    bool autoscale() const;
    void setTraceVisible(int trace, bool visible); // traces: axes 0..n-1, then the tip's
    bool traceVisible(int trace) const;

    // Where the toolbar's exports ask for a file: the dialog's title, the file name's tail
    // ("_plots.png", "_tracking.csv") and the filter; returns the path, empty = cancelled. The
    // host proposes a name from its job (default: a file dialog on "tracking<tail>").
    using SavePathAsker =
        std::function<QString(const QString& title, const QString& tail, const QString& filter)>;
    void setSavePathAsker(SavePathAsker ask);
    // Both plots stacked into one PNG / all kept samples as CSV; written atomically.
    bool exportPng(const QString& path, QString* error = nullptr);
    bool exportCsv(const QString& path, QString* error = nullptr);

    int sampleCount() const;            // samples kept in the ring
    std::uint64_t droppedCount() const; // samples dropped since clear()
    int plottedPointCount() const;      // points in the joint plot's first trace (tests, bench)
    std::uint64_t timerTicks() const;   // ticks of the ~30 Hz timer handled so far (tests)
    // Draws pending data now, as the internal ~30 Hz timer would. A host with its own display
    // tick calls it there and turns the timer's data redraws off (setHostDrivenRedraw(true)),
    // so the plots join that tick's window composition instead of causing one of their own
    // (costly with a QOpenGLWidget in the window). The timer still syncs the two plots' time
    // ranges after a drag or zoom.
    void redrawPending();
    void setHostDrivenRedraw(bool on);
    // Syncs and replots at once (tests, benchmark); returns the replot time in ms.
    double replotNow();

  signals:
    void pausedChanged(bool paused);

  protected:
    void showEvent(QShowEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;

  private:
    struct Impl;
    std::unique_ptr<Impl> d;
};

} // namespace cutcell::plots
