#include "ui/panels/state_lamps.h"

#include <QGridLayout>
#include <QPainter>
#include <QTimer>

namespace CutCell::ui {

using cutcell::EngineState;

Lamp::Lamp(const QString& text, QColor color, QWidget* parent)
    : QWidget(parent), text_(text), color_(color), timer_(new QTimer(this)) {
    setObjectName(QStringLiteral("lamp_") + text.toLower().remove('-'));
    timer_->setInterval(400);
    connect(timer_, &QTimer::timeout, this, [this] {
        phase_ = !phase_;
        update();
    });
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

QSize Lamp::sizeHint() const {
    const QFontMetrics fm(font());
    return {fm.horizontalAdvance(text_) + 40, std::max(30, fm.height() + 12)};
}

void Lamp::setLit(bool lit) {
    if (lit_ == lit) return;
    lit_ = lit;
    update();
}

void Lamp::setBlinking(bool blink) {
    if (blink_ == blink) return;
    blink_ = blink;
    phase_ = true;
    if (blink)
        timer_->start();
    else
        timer_->stop();
    update();
}

void Lamp::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const bool on = lit_ && (!blink_ || phase_);
    const int d = std::min(height() - 8, 22);
    const QRectF dot(4, (height() - d) / 2.0, d, d);
    QRadialGradient g(dot.center() - QPointF(d / 5.0, d / 5.0), d);
    g.setColorAt(0, on ? color_.lighter(160) : QColor(70, 74, 80));
    g.setColorAt(1, on ? color_ : QColor(38, 41, 46));
    p.setBrush(g);
    p.setPen(QPen(QColor(20, 20, 22), 1.5));
    p.drawEllipse(dot);
    p.setPen(on ? palette().color(QPalette::WindowText) : QColor(130, 136, 144));
    QFont f = font();
    f.setBold(on);
    p.setFont(f);
    p.drawText(QRectF(dot.right() + 8, 0, width() - dot.right() - 8, height()),
               Qt::AlignVCenter | Qt::AlignLeft, text_);
}

StateLamps::StateLamps(QWidget* parent) : QWidget(parent) {
    setObjectName("stateLamps");
    const std::array<std::pair<QString, QColor>, Count> spec{{
        {tr("Ready"), QColor(60, 200, 90)},
        {tr("Running"), QColor(60, 160, 255)},
        {tr("Paused"), QColor(255, 190, 40)},
        {tr("E-STOP"), QColor(240, 40, 40)},
        {tr("Fault"), QColor(255, 110, 30)},
        {tr("Torch"), QColor(255, 140, 0)},
    }};
    auto* g = new QGridLayout(this);
    g->setContentsMargins(4, 4, 4, 4);
    g->setVerticalSpacing(2);
    for (int i = 0; i < Count; ++i) {
        auto* l =
            new Lamp(spec[static_cast<size_t>(i)].first, spec[static_cast<size_t>(i)].second, this);
        lamps_[static_cast<size_t>(i)] = l;
        g->addWidget(l, i / 2, i % 2);
    }
}

void StateLamps::setState(EngineState s) {
    lamps_[Ready]->setLit(s == EngineState::Ready || s == EngineState::Completed);
    lamps_[Running]->setLit(s == EngineState::Running || s == EngineState::Homing ||
                            s == EngineState::Jogging);
    lamps_[Paused]->setLit(s == EngineState::Paused);
    lamps_[EStop]->setLit(s == EngineState::EmergencyStop);
    lamps_[EStop]->setBlinking(s == EngineState::EmergencyStop);
    lamps_[Fault]->setLit(s == EngineState::Fault);
    lamps_[Fault]->setBlinking(s == EngineState::Fault);
}

void Lamp::setText(const QString& text) {
    if (text == text_) return;
    text_ = text;
    update();
}

void StateLamps::setToolName(const QString& name) {
    lamps_[Torch]->setText(name.isEmpty() ? name : name.left(1).toUpper() + name.mid(1));
}

void StateLamps::setTorch(bool on) {
    lamps_[Torch]->setLit(on);
}

} // namespace CutCell::ui
