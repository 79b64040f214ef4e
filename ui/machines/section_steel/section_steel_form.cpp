#include "ui/machines/section_steel/section_steel_form.h"

#include "core/machines/section_steel/section_catalogue.h"
#include "core/machines/section_steel/section_kerf.h"
#include "core/machines/section_steel/section_steel_section.h"
#include "core/machines/section_steel/section_steel_spec.h"
#include "ui/forms/edited_spec.h"
#include "ui/forms/process_form.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <cmath>
#include <string>

namespace CutCell::ui {

using cutcell::Job;
using cutcell::section_steel::GrooveSpec;
using cutcell::section_steel::GrooveType;
using cutcell::section_steel::SectionDims;
using cutcell::section_steel::SectionFamily;
using cutcell::section_steel::SectionSteelSpec;

namespace {

SectionSteelSpec& spec(Job& j) {
    return CutCell::ui::editedSpec<SectionSteelSpec>(j); // a scratch spec for another machine's job
}
const SectionSteelSpec* specOf(const Job& j) {
    return j.machine_spec.as<SectionSteelSpec>();
}

// A catalogue series as the operator picks it: the designation's prefix, and for angles
// whether the legs are equal.
struct Series {
    const char* label;
    const char* prefix;
    int legs; // 0: any, 1: equal legs, 2: unequal legs
};
constexpr Series kSeries[] = {
    {"IPE", "IPE", 0},
    {"HEA", "HEA", 0},
    {"HEB", "HEB", 0},
    {"UPN", "UPN", 0},
    {"UPE", "UPE", 0},
    {QT_TRANSLATE_NOOP("CutCell::ui::SectionSteelSectionForm", "L (equal legs)"), "L", 1},
    {QT_TRANSLATE_NOOP("CutCell::ui::SectionSteelSectionForm", "L (unequal legs)"), "L", 2}};
constexpr int kSeriesCount = static_cast<int>(std::size(kSeries));
constexpr int kUserDefined = kSeriesCount; // the entry after the series

bool inSeries(const SectionDims& d, int series) {
    if (series < 0 || series >= kSeriesCount) return false;
    const Series& s = kSeries[series];
    const std::string prefix = d.designation.substr(0, d.designation.find(' '));
    if (prefix != s.prefix) return false;
    const bool equal = std::fabs(d.h_mm - d.b_mm) < 1e-9;
    return s.legs == 0 || (s.legs == 1) == equal;
}

int seriesOf(const SectionSteelSpec& s) {
    if (s.user_defined) return kUserDefined;
    for (int i = 0; i < kSeriesCount; ++i)
        if (inSeries(s.section, i)) return i;
    return kUserDefined;
}

} // namespace

QStringList SectionSteelSectionForm::seriesNames() {
    QStringList out;
    for (const Series& s : kSeries)
        out << tr(s.label);
    out << tr("User-defined dimensions");
    return out;
}

QStringList SectionSteelSectionForm::designationsOf(int series) {
    QStringList out;
    for (const SectionDims& d : cutcell::section_steel::sectionCatalogue())
        if (inSeries(d, series)) out << QString::fromStdString(d.designation);
    return out;
}

SectionSteelSectionForm::SectionSteelSectionForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    auto* note = new QLabel(
        tr("The section lies on the cutting table along x, its underside on the table; the end "
           "at x = 0 is cut. Catalogue dimensions after EN 10365:2017 (IPE, HEA, HEB, UPN, UPE) "
           "and EN 10056-1:2017 (angles); the root radii are drawn and cut."),
        this);
    note->setWordWrap(true);
    mainLayout()->addWidget(note);

    auto* cat = new QGroupBox(tr("Section"), this);
    auto* fc = new QFormLayout(cat);
    series_ = bindChoice(
        "section.series", seriesNames(),
        [](const Job& j) {
            const SectionSteelSpec* s = specOf(j);
            return s ? seriesOf(*s) : 0;
        },
        [](Job& j, int i) {
            SectionSteelSpec& s = spec(j);
            if (i >= kUserDefined) { // keep the dimensions, drop the designation
                s.user_defined = true;
                s.section.designation.clear();
                return;
            }
            // The member of the series nearest in height to the section shown.
            const SectionDims* best = nullptr;
            for (const SectionDims& d : cutcell::section_steel::sectionCatalogue())
                if (inSeries(d, i) && (!best || std::fabs(d.h_mm - s.section.h_mm) <
                                                    std::fabs(best->h_mm - s.section.h_mm)))
                    best = &d;
            if (!best) return;
            s.section = *best;
            s.user_defined = false;
        });
    addRow(fc, tr("Series"), series_, "");
    designation_ = new QComboBox(this);
    designation_->setObjectName("section.designation");
    alsoMark("section.designation", designation_);
    addRow(fc, tr("Designation"), designation_, "");
    shape_ = bindChoice(
        "section.family", {tr("I / H section"), tr("U channel"), tr("L angle")},
        [](const Job& j) {
            const SectionSteelSpec* s = specOf(j);
            return s ? static_cast<int>(s->section.family) : 0;
        },
        [](Job& j, int i) { spec(j).section.family = static_cast<SectionFamily>(i); });
    addRow(fc, tr("Shape (user-defined)"), shape_, "");
    const auto dim = [this](const char* key, auto member) {
        return bindDouble(key, 1, [member](Job& j) -> double& { return member(spec(j).section); });
    };
    dims_[0] = dim("section.h_mm", [](SectionDims& d) -> double& { return d.h_mm; });
    dims_[1] = dim("section.b_mm", [](SectionDims& d) -> double& { return d.b_mm; });
    dims_[2] = dim("section.tw_mm", [](SectionDims& d) -> double& { return d.tw_mm; });
    dims_[3] = dim("section.tf_mm", [](SectionDims& d) -> double& { return d.tf_mm; });
    dims_[4] = dim("section.r_mm", [](SectionDims& d) -> double& { return d.r_mm; });
    dims_[5] = dim("section.r2_mm", [](SectionDims& d) -> double& { return d.r2_mm; });
    addRow(fc, tr("Height h (L: vertical leg)"), dims_[0], "mm");
    addRow(fc, tr("Width b (L: horizontal leg)"), dims_[1], "mm");
    addRow(fc, tr("Web thickness tw (L: leg)"), dims_[2], "mm");
    addRow(fc, tr("Flange thickness tf (L: leg)"), dims_[3], "mm");
    addRow(fc, tr("Root radius r"), dims_[4], "mm");
    addRow(fc, tr("Toe radius r2 (U, L)"), dims_[5], "mm");
    addRow(fc, tr("Bar length"),
           bindDouble("section.length_mm", 0, [](Job& j) -> double& { return spec(j).length_mm; }),
           "mm");
    alsoMark("section", cat);
    mainLayout()->addWidget(cat);
    source_ = new QLabel(this);
    source_->setObjectName("sectionSource");
    source_->setWordWrap(true);
    mainLayout()->addWidget(source_);
    pieceBox_ = new QGroupBox(tr("Piece (from the detailing software)"), this);
    auto* fp = new QVBoxLayout(pieceBox_);
    piece_ = new QLabel(pieceBox_);
    piece_->setObjectName("pieceMarks");
    piece_->setTextFormat(Qt::PlainText); // a mark is text, never markup
    piece_->setWordWrap(true);
    piece_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    fp->addWidget(piece_);
    mainLayout()->addWidget(pieceBox_);
    // The process the section is cut with (the machine section's "process", after the section
    // and its piece): the cut chart gives this machine its kerf only (section_kerf.h); the row
    // is read at the section's thickest plate unless the job gives a thickness.
    addSubForm(new ProcessForm(editor, processPart(), this));
    mainLayout()->addStretch(1);

    // A new series or designation changes the dimensions shown (bound fields reload only when
    // the whole job is replaced).
    connect(series_, &QComboBox::currentIndexChanged, this, [this] {
        if (!loading()) refresh(this->editor()->job());
    });
    connect(designation_, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (loading() || refreshing_ || i < 0) return;
        const auto found =
            cutcell::section_steel::findSection(designation_->itemText(i).toStdString());
        if (!found) return;
        Job current = this->editor()->job();
        const QString was = QString::fromStdString(spec(current).section.designation);
        commit("section.designation", was, designation_->itemText(i), [&](Job& j) {
            spec(j).section = *found;
            spec(j).user_defined = false;
        });
        refresh(this->editor()->job());
    });
}

void SectionSteelSectionForm::reloadExtra(const Job& job) {
    refresh(job);
}

void SectionSteelSectionForm::refresh(const Job& job) {
    const SectionSteelSpec* s = specOf(job);
    if (!s) return;
    pieceBox_->setVisible(!s->piece.empty());
    const auto mark = [](const std::string& v) {
        return v.empty() ? QStringLiteral("-") : QString::fromStdString(v);
    };
    piece_->setText(tr("Order %1, drawing %2, phase %3, piece mark %4, steel %5, quantity %6 "
                       "(the job cuts one piece)")
                        .arg(mark(s->piece.order), mark(s->piece.drawing), mark(s->piece.phase),
                             mark(s->piece.mark), mark(s->piece.steel_grade))
                        .arg(s->piece.quantity));
    refreshing_ = true;
    const int series = seriesOf(*s);
    {
        const QSignalBlocker b1(series_), b2(designation_);
        series_->setCurrentIndex(series);
        designation_->clear();
        if (series < kUserDefined) {
            designation_->addItems(designationsOf(series));
            designation_->setCurrentText(QString::fromStdString(s->section.designation));
        }
        const double v[6] = {s->section.h_mm,  s->section.b_mm, s->section.tw_mm,
                             s->section.tf_mm, s->section.r_mm, s->section.r2_mm};
        for (int i = 0; i < 6; ++i) {
            const QSignalBlocker b(dims_[i]);
            dims_[i]->setValue(v[i]);
        }
        const QSignalBlocker b3(shape_);
        shape_->setCurrentIndex(static_cast<int>(s->section.family));
    }
    const bool user = series == kUserDefined;
    designation_->setEnabled(!user);
    shape_->setEnabled(user);
    for (QDoubleSpinBox* d : dims_)
        d->setEnabled(user);
    source_->setText(user ? tr("User-defined dimensions: checked against the section's own "
                               "limits (the root radius must leave a flat flange).")
                          : tr("%1 from the catalogue (%2 shape): the dimensions are the "
                               "standard's; choose \"User-defined dimensions\" to change them.")
                                .arg(QString::fromStdString(s->section.designation),
                                     QString::fromUtf8(toString(s->section.family))));
    refreshing_ = false;
}

ProcessPart SectionSteelSectionForm::processPart() {
    ProcessPart part;
    part.wallMm = [](const Job& j) {
        const SectionSteelSpec* s = specOf(j);
        return s ? cutcell::section_steel::steelPartThicknessMm(*s) : 0.0;
    };
    part.wallNote = tr("The section's thickest plate: the flange or the web, whichever is "
                       "thicker.");
    // As validate() refuses them (core/machines/section_steel/section_steel_module.cpp).
    const QString otherFigures = tr("Not used: the section-steel cutter takes only the kerf "
                                    "width from the cut chart.");
    for (std::size_t k = 1; k < cutcell::kCutFigureCount; ++k) {
        const auto f = static_cast<cutcell::CutFigure>(k);
        if (f == cutcell::CutFigure::KerfMm) continue;
        part.refused.push_back(
            {f, f == cutcell::CutFigure::CutSpeedMmMin
                    ? tr("Not used: the section-steel cutter cuts at its own speed (Cutting "
                         "speed along the outline, on the Motion & arms page).")
                    : otherFigures});
    }
    part.withoutChart = tr("No cut chart: the cut runs without kerf compensation.");
    return part;
}

SectionSteelEndCutForm::SectionSteelEndCutForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    auto* note = new QLabel(
        tr("The end is cut square or mitred (the cut plane turned about the section's vertical "
           "and horizontal axes), then the faces with a groove are bevelled by the groove arm: "
           "V = single bevel through the thickness, Y = single bevel with a root face, K = "
           "double bevel from both faces with a root face (ISO 9692-1)."),
        this);
    note->setWordWrap(true);
    mainLayout()->addWidget(note);
    auto* mitre = new QGroupBox(tr("Mitre"), this);
    auto* fm = new QFormLayout(mitre);
    for (const char* key : {"end_cut.mitre_vertical_deg", "end_cut.mitre_horizontal_deg"})
        addSectionRow(fm, sectionField(cutcell::section_steel::sectionSteelFields(), key), &spec);
    mainLayout()->addWidget(mitre);

    const char* const keys[2] = {"end_cut.flanges", "end_cut.web"};
    const QString titles[2] = {tr("Groove of the flanges (angles: horizontal leg)"),
                               tr("Groove of the web (angles: vertical leg)")};
    for (int g = 0; g < 2; ++g) {
        const auto groove = [g](Job& j) -> GrooveSpec& {
            return g == 0 ? spec(j).cut.flanges : spec(j).cut.web;
        };
        auto* box = new QGroupBox(titles[g], this);
        auto* fg = new QFormLayout(box);
        const std::string k = keys[g];
        type_[g] = bindChoice(
            k + ".groove",
            {tr("none (square)"), tr("V"), tr("Y (with root face)"), tr("K (double bevel)")},
            [g](const Job& j) {
                const SectionSteelSpec* s = specOf(j);
                return s ? static_cast<int>(g == 0 ? s->cut.flanges.type : s->cut.web.type) : 0;
            },
            [groove](Job& j, int i) { groove(j).type = static_cast<GrooveType>(i); });
        addRow(fg, tr("Type"), type_[g], "");
        angle_[g] = bindDouble(k + ".angle_deg", 1,
                               [groove](Job& j) -> double& { return groove(j).angle_deg; });
        addRow(fg, tr("Bevel angle"), angle_[g], "deg");
        rootFace_[g] = bindDouble(k + ".root_face_mm", 1,
                                  [groove](Job& j) -> double& { return groove(j).root_face_mm; });
        addRow(fg, tr("Root face"), rootFace_[g], "mm");
        alsoMark(k, box);
        mainLayout()->addWidget(box);
        connect(type_[g], &QComboBox::currentIndexChanged, this, [this] { enableGrooveFields(); });
    }

    // The setup: a K groove on the flanges needs a bevel on the face lying on the conveyor.
    auto* setupBox = new QGroupBox(tr("Setup (turning the section over)"), this);
    setupBox->setObjectName("setupBox");
    const QString why = setupToolTip();
    setupBox->setToolTip(why); // shown while the field has no issue tooltip of its own
    auto* fs = new QFormLayout(setupBox);
    setup_ = bindChoice(
        "end_cut.setup",
        {tr("1 - as loaded (underside on the conveyor)"),
         tr("2 - turned over 180° about its long axis")},
        [](const Job& j) {
            const SectionSteelSpec* s = specOf(j);
            return s ? s->cut.setup - 1 : 0;
        },
        [](Job& j, int i) { spec(j).cut.setup = i + 1; });
    addRow(fs, tr("Setup"), setup_, "");
    if (QWidget* label = fs->labelForField(setup_)) label->setToolTip(why);
    setupNote_ = new QLabel(setupBox);
    setupNote_->setObjectName("setupNote");
    setupNote_->setWordWrap(true);
    fs->addRow(setupNote_);
    // The box keeps its tooltip: only the combo is marked (marking clears a field's tooltip).
    mainLayout()->addWidget(setupBox);
    connect(setup_, &QComboBox::currentIndexChanged, this, [this] { enableGrooveFields(); });
    mainLayout()->addStretch(1);
}

QString SectionSteelEndCutForm::setupToolTip() {
    return tr("end_cut.setup - 1: the section as loaded, its underside on the conveyor: the end "
              "is cut and every face the torches reach is bevelled. A K groove (double bevel) on "
              "the flanges also needs a bevel on the underside of the bottom flange (angles: the "
              "horizontal leg), which lies on the conveyor. After setup 1 the operator turns the "
              "section over, 180° about its long axis, and runs setup 2: it cuts only that "
              "bevel, on the turned section (a channel's web and an angle's vertical leg change "
              "sides; the mitres are mirrored in the cell). Setup 2 without a K groove on the "
              "flanges has nothing to cut and is refused.");
}

void SectionSteelEndCutForm::reloadExtra(const Job&) {
    enableGrooveFields();
}

void SectionSteelEndCutForm::enableGrooveFields() {
    for (int g = 0; g < 2; ++g) {
        const auto t = static_cast<GrooveType>(type_[g]->currentIndex());
        angle_[g]->setEnabled(t != GrooveType::None);
        // V has none, but a left-over value must stay editable to clear it (it is refused).
        rootFace_[g]->setEnabled(t != GrooveType::None);
    }
    // What the job's setups do, in a sentence under the choice.
    if (!setup_ || !setupNote_) return; // during construction
    const bool k = static_cast<GrooveType>(type_[0]->currentIndex()) == GrooveType::K;
    const bool turned = setup_->currentIndex() == 1;
    setupNote_->setText(
        !k       ? tr("No K groove on the flanges: setup 1 cuts the whole end.")
        : turned ? tr("Setup 2 of 2: the section lies turned over; only the bevel on the underside "
                      "of the bottom flange (angles: horizontal leg), now on top, is cut.")
                 : tr("Setup 1 of 2: the underside of the bottom flange (angles: horizontal leg) "
                      "lies on the conveyor. Then turn the section over and run setup 2."));
}

} // namespace CutCell::ui
