#include "devices/machines/flying_saw/saw_cut_recorder.h"

#include <cstdio>

namespace cutcell {

SawCutRecorder::SawCutRecorder(const FlyingSawSpec& spec, FlyingSawSource* source)
    : spec_(spec), source_(source), meter_(spec.pieceCount() + 8),
      gauge_(static_cast<size_t>(spec.pieceCount()) + 8, 0.0),
      ordered_(static_cast<size_t>(spec.pieceCount()) + 8, 0.0) {}

void SawCutRecorder::feed(double q, double now_s) {
    meter_.feed(source_->bladeInWall(), source_->cutIndex(), q, now_s);
    // A cut closed: its piece's ordered length; the gauge reports it `delay` pieces later.
    while (seen_ < meter_.cuts().size()) {
        const CutRecord& c = meter_.cuts()[seen_];
        const size_t k = static_cast<size_t>(c.index);
        if (c.index >= 1 && k < ordered_.size()) {
            ordered_[k] = source_->orderedLength(c.index);
            if (seen_ >= 1)
                gauge_[k] =
                    meter_.cuts()[seen_ - 1].position_mm - c.position_mm - spec_.blade_kerf_mm;
            const int report = c.index - spec_.gauge_delay_pieces;
            if (spec_.gauge_enabled && report >= 1 && gauge_[static_cast<size_t>(report)] > 0)
                source_->reportGauge(report, gauge_[static_cast<size_t>(report)]);
        }
        ++seen_;
    }
}

std::vector<PieceRecord> SawCutRecorder::pieces() const {
    return meter_.pieces(spec_.blade_kerf_mm, [&](int p) {
        return p >= 0 && static_cast<size_t>(p) < ordered_.size() ? ordered_[static_cast<size_t>(p)]
                                                                  : 0.0;
    });
}

void SawCutRecorder::addToReport(json::Value& doc) const {
    const std::vector<PieceRecord> p = pieces();
    const LengthStats s = lengthStats(p, spec_.tolerance_mm);
    json::Array rows;
    for (const PieceRecord& r : p)
        rows.emplace_back(json::Object{{"piece", r.piece},
                                       {"ordered_mm", r.ordered_mm},
                                       {"length_mm", r.length_mm},
                                       {"error_mm", r.error_mm},
                                       {"cut_spread_mm", r.spread_mm}});
    doc.set("cut_lengths", json::Object{{"pieces_measured", s.count},
                                        {"error_mm_mean", s.mean},
                                        {"error_mm_std", s.std},
                                        {"error_mm_max_abs", s.max_abs},
                                        {"cpk", s.cpk},
                                        {"tolerance_mm", spec_.tolerance_mm},
                                        {"pieces", rows}});
}

std::string SawCutRecorder::summary(const std::string& outcome) const {
    const LengthStats s = lengthStats(pieces(), spec_.tolerance_mm);
    char b[200];
    std::snprintf(b, sizeof b, ": %d pieces, length error mean %.4f mm, std %.4f mm, max %.4f mm",
                  s.count, s.mean, s.std, s.max_abs);
    return outcome + b;
}

} // namespace cutcell
