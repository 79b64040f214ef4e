#pragma once
// Arc length travelled along a path of a given length at a cutting speed, with smooth cosine
// ramps of ramp_s at both ends (cruise in between); the ramps shorten on a path too short for
// them. Every machine that moves a torch along a path at the cut's speed uses it.
namespace cutcell {

class SpeedProfile {
  public:
    SpeedProfile(double length_mm, double speed_mm_s, double ramp_s);
    double duration() const { return duration_; }
    double distance(double t) const;
    double speed(double t) const;

  private:
    double length_, v_, ramp_, duration_;
};

} // namespace cutcell
