#pragma once
// The section-steel cutter's section and end-cut pages (Job::machine_spec, core/machines/
// section_steel/section_steel_spec.h). The keys are those of the machine section as validate()
// names them ("section.h_mm", "end_cut.web.angle_deg", ...), so a bad value is marked on its
// field with the core's message (key, value, unit, limit).
#include "ui/forms/job_form.h"

class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;

namespace CutCell::ui {

struct ProcessPart;

// The section: a catalogue series (IPE, HEA, HEB, UPN, UPE, equal and unequal angles) and its
// designation, or user-defined dimensions (shape, h, b, tw, tf, r); the bar's length; the
// piece's marks (order, drawing, phase, piece mark, steel grade, quantity), shown read-only;
// the process it is cut with (ProcessForm: the cut chart, its kerf).
class SectionSteelSectionForm : public JobForm {
    Q_OBJECT
  public:
    explicit SectionSteelSectionForm(JobEditor* editor, QWidget* parent = nullptr);

    // The series offered (the last entry is "user-defined dimensions").
    static QStringList seriesNames();
    // The catalogue designations of series i, in the catalogue's order.
    static QStringList designationsOf(int series);
    QComboBox* seriesBox() const { return series_; }
    QComboBox* designationBox() const { return designation_; }

    // The cut chart as this machine takes it: the part's wall is the section's thickest plate
    // (steelPartThicknessMm), only the kerf's override is used (the speed is motion.speed_mm_s).
    static ProcessPart processPart();

  protected:
    void reloadExtra(const cutcell::Job& job) override;

  private:
    // Fills the designation list for the job's series and shows the job's dimensions.
    void refresh(const cutcell::Job& job);
    QComboBox* series_ = nullptr;
    QComboBox* designation_ = nullptr;
    QComboBox* shape_ = nullptr;
    QDoubleSpinBox* dims_[6] = {}; // h, b, tw, tf, r, r2
    QLabel* source_ = nullptr;
    QGroupBox* pieceBox_ = nullptr; // the piece's marks (a DSTV file's header), when it has any
    QLabel* piece_ = nullptr;
    bool refreshing_ = false;
};

// The end cut: mitres about both section axes, the groove of the flanges and of the web
// (type V / Y / K after ISO 9692-1, bevel angle, root face) and the setup (end_cut.setup: 1 as
// loaded, 2 turned over for a K groove's bevel on the face that lay on the conveyor).
class SectionSteelEndCutForm : public JobForm {
    Q_OBJECT
  public:
    explicit SectionSteelEndCutForm(JobEditor* editor, QWidget* parent = nullptr);

  protected:
    void reloadExtra(const cutcell::Job& job) override;

    // What a setup is and why (the setup field's tooltip).
    static QString setupToolTip();

  private:
    void enableGrooveFields();
    QComboBox* type_[2] = {};          // flanges, web
    QComboBox* setup_ = nullptr;       // end_cut.setup - 1
    QLabel* setupNote_ = nullptr;      // what the job's setups do
    QDoubleSpinBox* angle_[2] = {};    // deg
    QDoubleSpinBox* rootFace_[2] = {}; // mm
};

} // namespace CutCell::ui
