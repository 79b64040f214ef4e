#pragma once
// Indicator lamps: Ready, Running, Paused, E-STOP, Fault, Torch. Each lamp is lit in its own
// colour and dark grey when off; the E-STOP and Fault lamps blink while latched.
//
// Threading contract: GUI thread only.
#include "core/engine/engine_types.h"

#include <QWidget>

#include <array>

class QTimer;

namespace CutCell::ui {

class Lamp : public QWidget {
    Q_OBJECT
  public:
    Lamp(const QString& text, QColor color, QWidget* parent = nullptr);
    void setLit(bool lit);
    void setText(const QString& text);
    QString text() const { return text_; }
    void setBlinking(bool blink);
    bool isLit() const { return lit_; }
    QSize sizeHint() const override;

  protected:
    void paintEvent(QPaintEvent*) override;

  private:
    QString text_;
    QColor color_;
    bool lit_ = false;
    bool blink_ = false;
    bool phase_ = true;
    QTimer* timer_;
};

class StateLamps : public QWidget {
    Q_OBJECT
  public:
    enum Which { Ready, Running, Paused, EStop, Fault, Torch, Count };
    explicit StateLamps(QWidget* parent = nullptr);

    void setState(cutcell::EngineState state);
    void setTorch(bool on);
    // The process tool's lamp is named as the machine names its tool ("Saw", "Cutter").
    void setToolName(const QString& name);
    const Lamp* lamp(Which w) const { return lamps_[static_cast<size_t>(w)]; }

  private:
    std::array<Lamp*, Count> lamps_{};
};

} // namespace CutCell::ui
