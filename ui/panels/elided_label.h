#pragma once
// A one-line label that never widens its window: however long its text (a bus failure naming
// six nodes, a path), it asks for little width, shows what fits with "…" and keeps the whole
// text in its tooltip. A QLabel asks for its whole text's width as its minimum: in the status
// bar or a tab that pushed the window past the screen and the E-STOP column off it.
//
// Threading contract: GUI thread only.
#include <QLabel>

namespace CutCell::ui {

class ElidedLabel : public QLabel {
    Q_OBJECT
  public:
    explicit ElidedLabel(const QString& text = {}, QWidget* parent = nullptr);

    // The whole text (what text() shows may be elided).
    QString fullText() const { return full_; }
    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

  public slots:
    void setFullText(const QString& text);

  protected:
    void resizeEvent(QResizeEvent* event) override;

  private:
    void refit();
    QString full_;
};

} // namespace CutCell::ui
