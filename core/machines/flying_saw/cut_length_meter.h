#pragma once
// The figure that matters to the mill: the length of every piece, measured as the distance
// along the pipe between consecutive cut positions (minus the kerf). A cut's position is where
// the blade is on the pipe while it is in the wall: q = carriage (actual) - line (true) in the
// pipe's own coordinate, averaged over the time in the wall; its spread (max - min) shows how
// far the cut moved on the pipe during the cut (a line-speed change during a cut widens it).
//
// feed() is allocation-free once constructed with the number of cuts expected.
#include <cmath>
#include <vector>

namespace cutcell {

struct CutRecord {
    int index = 0;
    double position_mm = 0; // mean q while in the wall
    double spread_mm = 0;   // max - min of q while in the wall
    double time_s = 0;      // when the blade left the wall
};

struct PieceRecord {
    int piece = 0; // 1-based: between cut piece-1 and cut piece
    double ordered_mm = 0;
    double length_mm = 0;
    double error_mm = 0;  // length - ordered
    double spread_mm = 0; // the larger cut spread of its two ends
};

struct LengthStats {
    int count = 0;
    double mean = 0, std = 0, max_abs = 0, cpk = 0;
};

LengthStats lengthStats(const std::vector<PieceRecord>& pieces, double tolerance_mm,
                        int skipFirst = 0);

class CutLengthMeter {
  public:
    explicit CutLengthMeter(int expectedCuts = 256) {
        cuts_.reserve(static_cast<size_t>(expectedCuts));
    }
    // Once per cycle: whether the blade is in the wall, which cut, q (mm), the time.
    void feed(bool inWall, int cutIndex, double q, double t);
    const std::vector<CutRecord>& cuts() const { return cuts_; }
    // Pieces from consecutive cuts (ordered(k) gives the ordered length of piece k).
    template <class Ordered>
    std::vector<PieceRecord> pieces(double kerf_mm, Ordered ordered) const {
        std::vector<PieceRecord> out;
        for (size_t i = 1; i < cuts_.size(); ++i) {
            if (cuts_[i].index != cuts_[i - 1].index + 1) continue;
            PieceRecord p;
            p.piece = cuts_[i].index;
            p.ordered_mm = ordered(p.piece);
            p.length_mm = cuts_[i - 1].position_mm - cuts_[i].position_mm - kerf_mm;
            p.error_mm = p.length_mm - p.ordered_mm;
            p.spread_mm = std::fmax(cuts_[i - 1].spread_mm, cuts_[i].spread_mm);
            out.push_back(p);
        }
        return out;
    }

  private:
    void close(double t);
    std::vector<CutRecord> cuts_;
    bool open_ = false;
    int index_ = -1;
    double sum_ = 0, min_ = 0, max_ = 0;
    long n_ = 0;
};

} // namespace cutcell
