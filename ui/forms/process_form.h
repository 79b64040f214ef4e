#pragma once
// The cutting process (issue 24): the cut chart's entry the torch cuts with (process, material,
// consumable set, thickness: the part's wall unless given), the chart's row at that thickness,
// and an override per figure, saved with the job and shown as such. The charts are the active
// library (core/process/process_spec.h). Keys process.*.
#include "core/process/cut_chart.h"
#include "ui/forms/job_form.h"

#include <array>
#include <functional>
#include <utility>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace CutCell::ui {

// What the machine whose page shows the form makes of the chart; the page says it (the form
// knows no machine).
struct ProcessPart {
    // The part's wall: the thickness the chart's row is read at unless the job gives one (the
    // cut pipe's wall, a section's thickest plate).
    std::function<double(const cutcell::Job&)> wallMm;
    // What "the part's wall" is on this machine (the check box's tooltip); empty: none.
    QString wallNote;
    // The figures whose override the machine refuses, each with the reason: shown read-only
    // with it (an override the job already has can still be removed).
    std::vector<std::pair<cutcell::CutFigure, QString>> refused;
    // The note without a chart; empty: the Cut page's ("the cut runs at the Cut page's speed").
    QString withoutChart;
};

class ProcessForm : public JobForm {
    Q_OBJECT
  public:
    ProcessForm(JobEditor* editor, ProcessPart part, QWidget* parent = nullptr);

    // A process and a figure as the form shows them ("Plasma", "Kerf width [mm]"); the
    // cut-chart editor (ui/panels/cut_charts_dialog.h) names its columns alike.
    static QString processTitle(cutcell::CutProcess p);
    static QString figureHeader(cutcell::CutFigure f);
    // Opens the cut-chart editor on the job's chart ("Cut charts..."); after a save the form
    // shows the new table.
    void openCutCharts();

  protected:
    void reloadExtra(const cutcell::Job& job) override;

  private:
    void buildFigureRows();
    void setUsed(bool on);
    void setFigureOverridden(int figure, bool on);
    void setFigureValue(int figure, double v);
    double partWallMm(const cutcell::Job& job) const { return part_.wallMm(job); }
    // The reason the machine refuses the figure's override; empty when it takes it.
    QString refusal(cutcell::CutFigure f) const;

    ProcessPart part_;

    QCheckBox* used_ = nullptr;
    QComboBox* process_ = nullptr;
    QComboBox* material_ = nullptr;
    QComboBox* consumable_ = nullptr;
    QCheckBox* partWall_ = nullptr;
    QDoubleSpinBox* thickness_ = nullptr;
    QTableWidget* figures_ = nullptr;
    QLabel* chart_ = nullptr;
    QPushButton* editCharts_ = nullptr;
    std::array<QCheckBox*, 8> overrideBox_{};
    std::array<QDoubleSpinBox*, 8> valueBox_{};
    bool refreshing_ = false;
};

} // namespace CutCell::ui
