#include "ui/panels/progress_panel.h"

#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>

#include <algorithm>
#include <cmath>

namespace CutCell::ui {

ProgressPanel::ProgressPanel(QWidget* parent)
    : QWidget(parent), state_(new QLabel(this)), bar_(new QProgressBar(this)),
      percent_(new QLabel(this)), elapsed_(new QLabel(this)), remaining_(new QLabel(this)),
      points_(new QLabel(this)) {
    setObjectName("progressPanel");
    auto* g = new QGridLayout(this);
    g->setContentsMargins(6, 6, 6, 6);
    state_->setObjectName("stateText");
    g->addWidget(state_, 0, 0, 1, 2);
    percent_->setObjectName("percentText");
    percent_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    g->addWidget(percent_, 0, 2, 1, 2);
    bar_->setRange(0, 1000);
    bar_->setTextVisible(false);
    bar_->setMinimumHeight(22);
    g->addWidget(bar_, 1, 0, 1, 4);
    const auto caption = [this](const QString& t) {
        auto* l = new QLabel(t, this);
        l->setObjectName("caption");
        return l;
    };
    g->addWidget(caption(tr("Elapsed")), 2, 0);
    g->addWidget(caption(tr("Remaining")), 2, 1);
    g->addWidget(caption(tr("Point")), 2, 2, 1, 2);
    for (auto* l : {elapsed_, remaining_, points_})
        l->setObjectName("bigValue");
    g->addWidget(elapsed_, 3, 0);
    g->addWidget(remaining_, 3, 1);
    g->addWidget(points_, 3, 2, 1, 2);
    clear();
}

QString ProgressPanel::formatDuration(double s) {
    if (!std::isfinite(s) || s < 0) s = 0;
    const auto total = static_cast<long long>(std::llround(s * 10));
    const long long tenths = total % 10, secs = (total / 10) % 60, mins = total / 600;
    return QStringLiteral("%1:%2.%3")
        .arg(mins, 2, 10, QChar('0'))
        .arg(secs, 2, 10, QChar('0'))
        .arg(tenths);
}

void ProgressPanel::setSample(const cutcell::TelemetrySample& s) {
    const double p = std::clamp(s.progress, 0.0, 1.0);
    const int value = static_cast<int>(std::lround(p * 1000));
    if (value != bar_->value()) {
        // QProgressBar::setValue() repaints synchronously when the fill moves a pixel; with the
        // 3D view's QOpenGLWidget in the window that is a whole-window GL composition (~20 ms on
        // llvmpipe) inside the telemetry tick. With updates off it is a no-op; re-enabling
        // schedules an update() that joins the tick's single composition.
        bar_->setUpdatesEnabled(false);
        bar_->setValue(value);
        bar_->setUpdatesEnabled(true);
    }
    percent_->setText(QStringLiteral("%1 %").arg(p * 100.0, 0, 'f', 1));
    elapsed_->setText(formatDuration(s.elapsed_s));
    remaining_->setText(formatDuration(s.remaining_s));
    // The engine counts knots passed from 0; the operator reads "point n of N" from 1.
    const auto shown = s.point_count ? std::min(s.point_index + 1, s.point_count) : 0u;
    points_->setText(QStringLiteral("%1 / %2").arg(shown).arg(s.point_count));
    state_->setText(QString::fromLatin1(cutcell::toString(s.state)));
}

void ProgressPanel::setPlannedTotals(std::uint32_t points, double duration_s) {
    points_->setText(QStringLiteral("0 / %1").arg(points));
    remaining_->setText(formatDuration(duration_s));
}

void ProgressPanel::clear() {
    bar_->setValue(0);
    percent_->setText(QStringLiteral("0.0 %"));
    elapsed_->setText(formatDuration(0));
    remaining_->setText(formatDuration(0));
    points_->setText(QStringLiteral("0 / 0"));
    state_->setText(tr("Idle"));
}

QString ProgressPanel::percentText() const {
    return percent_->text();
}
QString ProgressPanel::pointsText() const {
    return points_->text();
}

} // namespace CutCell::ui
