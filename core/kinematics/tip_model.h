#pragma once
// Torch tip position (mm) for joint values; used for the Cartesian tracking error by the
// offline simulation and by the motion engine. Implementations are immutable: const methods
// may be called from any thread, allocation-free.
#include "core/common/types.h"

namespace cutcell {

class TipModel {
  public:
    virtual ~TipModel() = default;
    virtual Vec3 tip(const JointVector& q) const = 0;
    // tip() of two samples (commanded and actual) at once; a model may share work between
    // them, each result equal to tip() bit for bit.
    virtual void tipPair(const JointVector& qa, const JointVector& qb, Vec3& a, Vec3& b) const {
        a = tip(qa);
        b = tip(qb);
    }
    // The tip (given in the base frame) seen from the work piece, for machines that move the
    // work (the pipe chuck). Default: the work does not move.
    virtual Vec3 tipOnWork(const JointVector& q, const Vec3& tipBase) const {
        (void)q;
        return tipBase;
    }
};

} // namespace cutcell
