#pragma once
// The flying saw's figures page (the mill's figure first), from the edited job's plan (core
// planFlyingSaw) and the offline simulation of its queue (core simulateFlyingSaw: the simulated
// line with its wander, steps and slip, the roller encoder, the motion source the engine runs, the
// carriage's servo, the length gauge): the carriage's s, v and a over one cycle at the nominal line
// speed with the periods AB, BC, CE, EF, FG, GH, HI each drawn in its own colour; the cam table
// (radial feed against the turntable angle, both blades); the cut-length error of every piece with
// its mean, standard deviation and Cpk against the job's tolerance. Exports the cam table as CSV
// (the core's camTableCsv, written atomically).
// Built only with the plots library (CUTCELL_HAVE_PLOTS).
//
// Threading contract: GUI thread only (a simulation of the shipped job's ten pieces takes a few
// ms; 200 pieces ~0.2 s).
#include "ui/forms/job_form.h"

class QLabel;
class QPushButton;

namespace cutcell::plots {
class XyFiguresWidget;
}

namespace CutCell::ui {

class FlyingSawFiguresForm : public JobForm {
    Q_OBJECT
  public:
    enum Panel { Pieces, CarriageS, CarriageV, CarriageA, Cam, PanelCount };

    explicit FlyingSawFiguresForm(JobEditor* editor, QWidget* parent = nullptr);

    // Plans the edited job, simulates its queue and draws the figures; false + *why (the plan's
    // problem with its figures) when it cannot.
    bool simulate(QString* why = nullptr);
    // Writes the edited job's cam table CSV to `path` atomically; false + *error naming the file.
    bool exportCamCsv(const QString& path, QString* error);

    cutcell::plots::XyFiguresWidget* figures() const { return figures_; }
    QLabel* summary() const { return summary_; }
    QLabel* pieceStats() const { return stats_; }

  private:
    cutcell::plots::XyFiguresWidget* figures_ = nullptr;
    QLabel* summary_ = nullptr;
    QLabel* stats_ = nullptr;
    QPushButton* simulate_ = nullptr;
    QPushButton* export_ = nullptr;
};

} // namespace CutCell::ui
