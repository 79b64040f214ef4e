#pragma once
// The flying saw's own keys (Job::machine_spec, core/machines/flying_saw/flying_saw_spec.h) on
// two pages: the tube, the line with its measuring roller and the queue of cut lengths; the
// carriage, the saw's cycle, the blade, the length gauge and the simulated line. The keys are
// those of the machine section as the module's validate() names them ("tube.wall_mm", ...).
#include "ui/forms/job_form.h"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace CutCell::ui {

class FlyingSawTubeLineForm : public JobForm {
    Q_OBJECT
  public:
    explicit FlyingSawTubeLineForm(JobEditor* editor, QWidget* parent = nullptr);

    QTableWidget* queueTable() const { return queue_; }
    // Appends a row (length, count) to the queue (the Add button).
    void addQueueRow(double length_mm, int count);
    // While the machine moves only the queue stays editable, with "Send to the running line".
    void setEditingLocked(bool locked) override;
    // Publishes the edited job's queue to the running line's motion source (the button): it
    // replaces the pieces not yet begun, from the next piece (FlyingSawSource::queue()).
    // False + *why when there is no running flying-saw program, the queue has issues or the
    // previous change was not taken yet.
    bool sendQueueToRunningLine(QString* why = nullptr);
    QPushButton* sendQueueButton() const { return send_; }

  protected:
    void reloadExtra(const cutcell::Job& job) override;

  private:
    void showShapeRows(int shape); // 0 round, 1 square, 2 rectangular
    void appendQueueRow(double length_mm, int count);
    void loadQueue(const cutcell::Job& job);
    void removeQueueRow(int row);
    void writeQueue();
    void updateDerived(const cutcell::Job& job);

    QFormLayout* tubeRows_ = nullptr;
    int diameterRow_ = -1, widthRow_ = -1, heightRow_ = -1, cornerRow_ = -1;
    QComboBox* shape_ = nullptr;
    QDoubleSpinBox* width_ = nullptr;
    QDoubleSpinBox* height_ = nullptr;
    QTableWidget* queue_ = nullptr;
    QLabel* queueTotal_ = nullptr;
    QLabel* sendNote_ = nullptr;
    QPushButton* send_ = nullptr;
    QGroupBox* queueGroup_ = nullptr;
    QWidget* tolerance_ = nullptr;
    QLabel* resolution_ = nullptr;
};

class FlyingSawCarriageSawForm : public JobForm {
    Q_OBJECT
  public:
    explicit FlyingSawCarriageSawForm(JobEditor* editor, QWidget* parent = nullptr);
};

} // namespace CutCell::ui
