#include "core/machines/flying_saw/cut_length_meter.h"

#include <algorithm>

namespace cutcell {

void CutLengthMeter::close(double t) {
    if (!open_) return;
    open_ = false;
    if (n_ == 0 || cuts_.size() == cuts_.capacity()) return; // never grows in the cycle
    CutRecord c;
    c.index = index_;
    c.position_mm = sum_ / static_cast<double>(n_);
    c.spread_mm = max_ - min_;
    c.time_s = t;
    cuts_.push_back(c);
}

void CutLengthMeter::feed(bool inWall, int cutIndex, double q, double t) {
    if (open_ && (!inWall || cutIndex != index_)) close(t);
    if (!inWall) return;
    if (!open_) {
        open_ = true;
        index_ = cutIndex;
        sum_ = 0;
        n_ = 0;
        min_ = max_ = q;
    }
    sum_ += q;
    ++n_;
    min_ = std::min(min_, q);
    max_ = std::max(max_, q);
}

LengthStats lengthStats(const std::vector<PieceRecord>& pieces, double tolerance_mm,
                        int skipFirst) {
    LengthStats s;
    double sum = 0;
    for (size_t i = static_cast<size_t>(std::max(skipFirst, 0)); i < pieces.size(); ++i) {
        sum += pieces[i].error_mm;
        s.max_abs = std::max(s.max_abs, std::fabs(pieces[i].error_mm));
        ++s.count;
    }
    if (s.count == 0) return s;
    s.mean = sum / s.count;
    double ss = 0;
    for (size_t i = static_cast<size_t>(std::max(skipFirst, 0)); i < pieces.size(); ++i)
        ss += (pieces[i].error_mm - s.mean) * (pieces[i].error_mm - s.mean);
    s.std = s.count > 1 ? std::sqrt(ss / (s.count - 1)) : 0;
    // Cpk against +-tolerance around the ordered length; a zero spread caps it (no infinity).
    const double margin = std::min(tolerance_mm - s.mean, s.mean + tolerance_mm);
    s.cpk = margin / (3 * std::max(s.std, 1e-9));
    s.cpk = std::min(s.cpk, 1e6);
    return s;
}

} // namespace cutcell
