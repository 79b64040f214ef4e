#pragma once
// Look of the 3D view: view presets and the colours of everything drawn (RGB in 0..1).
// The pixel test (tests/view) looks for these colours, so keep them distinct in hue:
//   pipe       steel grey-blue   (blue clearly above red)
//   mating     pale cyan wireframe (ghost)
//   path       amber/yellow      (planned, reachable)
//   done       bright green      (the part already cut)
//   unreachable red
//   torch      orange body, copper nozzle, blue-white flame while the torch is on, a white
//              arrow at the tip along the cutting direction
//   arm        light grey links, dark graphite joints
//   background dark blue-grey gradient, floor grid slightly lighter
namespace cutcell::view3d {

enum class ViewPreset { Iso, Front, Top, FollowTorch };

struct Rgb {
    double r, g, b;
};

namespace colours {
inline constexpr Rgb kPipe{0.50, 0.60, 0.76};
inline constexpr Rgb kPipeInner{0.36, 0.40, 0.48};
inline constexpr Rgb kMating{0.45, 0.70, 0.80};
inline constexpr double kMatingOpacity = 1.0; // wireframe ghost (opaque: no OIT pass)
inline constexpr Rgb kPath{1.00, 0.78, 0.05};
inline constexpr Rgb kDone{0.15, 1.00, 0.25};
inline constexpr Rgb kStopMark{1.00, 0.20, 0.85}; // where a run stopped (cut recovery)
inline constexpr Rgb kUnreachable{1.00, 0.08, 0.08};
inline constexpr Rgb kTorchBody{1.00, 0.42, 0.02};
inline constexpr Rgb kNozzle{0.92, 0.50, 0.18};
inline constexpr Rgb kFlame{0.55, 0.80, 1.00};
inline constexpr Rgb kDirection{0.95, 0.95, 0.95}; // arrow: cutting direction at the tip
inline constexpr Rgb kArmLink{0.82, 0.82, 0.80};
inline constexpr Rgb kArmJoint{0.22, 0.23, 0.26};
inline constexpr Rgb kMachine{0.30, 0.32, 0.36}; // chuck, headstock, robot pedestal
inline constexpr Rgb kBackgroundBottom{0.07, 0.08, 0.10};
inline constexpr Rgb kBackgroundTop{0.20, 0.23, 0.29};
inline constexpr Rgb kGrid{0.28, 0.31, 0.36};
inline constexpr Rgb kText{0.85, 0.88, 0.92};
} // namespace colours

} // namespace cutcell::view3d
