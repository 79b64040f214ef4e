#pragma once
// A row of static x-y figures (a few panels, each with named curves drawn in the order of their
// points, so a phase diagram y against y' is a curve too), for offline results a machine shows
// beside its live plots (the quick-return cutter's velocity profile, phase diagram and
// velocity error). QCustomPlot stays behind the pimpl.
//
// Tick labels are written in the C locale (decimal point), whatever the default locale.
//
// Threading contract: GUI thread only.
#include <QColor>
#include <QString>
#include <QVector>
#include <QWidget>

#include <memory>
#include <vector>

namespace cutcell::plots {

struct XyCurve {
    QString name;
    QVector<double> x, y; // same length; a non-finite point leaves a gap
    QColor colour;
    bool dashed = false;
};

class XyFiguresWidget : public QWidget {
    Q_OBJECT
  public:
    // The panels side by side (Horizontal) or stacked (Vertical, for a narrow dock).
    XyFiguresWidget(int panels, Qt::Orientation orientation, QWidget* parent = nullptr);
    // The panels in a grid of `columns`, row by row (e.g. four controllers side by side); the
    // last panel spans the rest of its row. Narrower than `columns` panels need, the grid has
    // fewer columns (one at least) and more rows: a narrow pane never scrolls sideways.
    XyFiguresWidget(int panels, int columns, QWidget* parent = nullptr);
    ~XyFiguresWidget() override;

    int panelCount() const;
    void setPanel(int panel, const QString& title, const QString& xLabel, const QString& yLabel);
    // Replaces the panel's curves and rescales its axes to them.
    void setCurves(int panel, const std::vector<XyCurve>& curves);
    // Where the panel's legend sits inside its axes (default top right).
    void setLegendAlignment(int panel, Qt::Alignment alignment);
    // The panel's legend: hidden (columns 0) or in rows of `columns` entries at its top left
    // (default: one column at the top right).
    void setLegendColumns(int panel, int columns);
    int curveCount(int panel) const;
    int pointCount(int panel) const; // drawn points over the panel's curves

  protected:
    void resizeEvent(QResizeEvent* event) override;

  private:
    void arrange(int columns);
    struct Impl;
    std::unique_ptr<Impl> d;
};

} // namespace cutcell::plots
