#pragma once
// A walker any student can open: one self-contained HTML file (inline JavaScript, a 2D
// canvas, nothing fetched) that animates a Fourier walker (METHOD §3) as a point-light
// display seen by the orthographic camera of METHOD §5.
//
// What the page computes, and what htmlWalkerDotsPx computes the same way in C++:
//
//   walker time   t_w(τ) = speed · τ                 τ: seconds since the page started (s)
//   cycle angle   θ = ω (t0 + t_w) + φ,  t0 = (2π · startPhase01 − φ) / ω
//                 so θ = 2π · startPhase01 at τ = 0: startPhase01 is the viewer's phase
//                 (ui's frameAtPhase), whatever the walker's own φ
//   posture       p = p0 + p1 sin θ + q1 cos θ + p2 sin 2θ + q2 cos 2θ    (synthesizeFrames)
//   progression   y += 1000 · translateSpeedMps · t_w (mm) when translate is on
//   view          u = x cos α + y sin α,  d = −x sin α + y cos α           (METHOD §5)
//                 v = z cos ε + d sin ε   (ε the elevation, the camera tilted down by ε as in
//                 docs/CAMERA.md; ε = 0 gives v = z, the viewer's view)
//   canvas        X = centreXPx + pxPerMm · u,   Y = centreYPx − pxPerMm · v   (CSS pixels,
//                 (0, 0) the canvas's top-left corner, pixel i covering [i, i + 1))
//                 the progression's offset wraps (below) so the walker re-enters the canvas.
//
// The mm → pixel mapping (htmlCanvasMapping) is fixed when the file is written and written
// into it; the page's controls (play/pause, α, speed, lines) never change it, so turning
// the walker does not rescale it:
//   - Fit (default): the walker over one cycle (360 samples of θ), seen from every α, fits
//     the canvas inside a margin of dotRadiusPx + 5 % of the canvas's smaller side. R is the
//     largest horizontal distance √(x² + y²) of any joint from the vertical axis (it bounds |u|
//     at every α); the vertical extent is [min(z cos ε − ρ |sin ε|), max(z cos ε + ρ |sin ε|)]
//     over the samples (ρ each sample's √(x² + y²)). pxPerMm is the largest scale at which
//     2R and that extent both fit; u = 0 is the canvas's centre column, the extent is centred
//     vertically.
//   - Viewer: the viewer's standard 2D input view (ui/panels/input_view_panel.cpp): 2350 mm
//     of height across the canvas, u = 0 at the centre column, v = 975 mm at the centre row,
//     the same for every walker (walkers compare by size).
// Wrapping: the progression's pixel offset (ox, oy) = pxPerMm · Δy · (sin α, −sin ε cos α)
// wraps as o ↦ ((o + P/2) mod P) − P/2, with P = wrapXPx = width + 2 R pxPerMm
// horizontally and P = wrapYPx = height + (vHi − vLo) pxPerMm vertically: the walker leaves
// the canvas whole before it comes back on the other side. At τ = 0 the offset is 0.
//
// Core only (Eigen and the standard library). The CLI's `export-html` and the viewer's export
// call writeWalkerHtml.

#include <Eigen/Core>
#include <filesystem>
#include <string>

namespace ew {

// [SECTION] The walker and the display

// The viewer's standard 2D input view (ui/panels/input_view_panel.cpp frames with these):
// this much height across the view, this v at its centre row, u = 0 at its centre column.
inline constexpr double kViewerViewHeightMm = 2350.0;
inline constexpr double kViewerViewCentreVMm = 975.0;

struct HtmlWalker {
  Eigen::VectorXd w;       // 225: [p0, p1, q1, p2, q2], mm (METHOD §3)
  double omegaRadS = 0.0;  // ω, rad/s, > 0
  double phaseRad = 0.0;   // φ, rad
  std::string name;        // what the walker is, shown on the page ("mean walker of …")
};

// The viewer's themes: dark, light (a lit room), projector (black, for a washed-out projector).
enum class HtmlTheme { Dark, Light, Projector };
enum class HtmlFraming { Fit, Viewer };

struct HtmlWalkerSettings {
  double viewAngleDeg = 90.0;      // α, degrees (METHOD §5): +90 shows the walker's right side
  double elevationDeg = 0.0;       // ε in [−90, 90]: > 0 looks down on the walker
  double playbackSpeed = 1.0;      // walker seconds per second, in [−5, 5]; < 0 walks backwards
  double startPhase01 = 0.0;       // the cycle's fraction θ / 2π at τ = 0, finite
  bool lines = false;              // the 14 bones (kBones) drawn behind the dots
  bool translate = false;          // overground (the walker progresses) or treadmill
  double translateSpeedMps = 1.3;  // progression speed, m/s, in [0, 10]
  int widthPx = 800;               // canvas size in CSS pixels, each in [64, 4096]
  int heightPx = 600;
  double dotRadiusPx = 5.0;  // in (0, 50]
  HtmlTheme theme = HtmlTheme::Dark;
  std::string dotColour;         // "#rrggbb"; empty: the theme's
  std::string backgroundColour;  // "#rrggbb"; empty: the theme's
  HtmlFraming framing = HtmlFraming::Fit;
  std::string title = "A point-light walker";  // at most 200 characters, HTML-escaped
  std::string caption;                         // at most 2000 characters, HTML-escaped
};

// The theme's colours ("#rrggbb"), the settings' own where given.
struct HtmlColours {
  std::string background, dot, line, text;
};
HtmlColours htmlColours(const HtmlWalkerSettings& settings);

// [SECTION] The mapping and the dots

struct HtmlCanvasMapping {
  double pxPerMm = 0.0;
  double centreXPx = 0.0;  // where u = 0 is
  double centreYPx = 0.0;  // where v = 0 is
  double wrapXPx = 0.0;    // the progression's wrap periods (above)
  double wrapYPx = 0.0;
};

// The mapping written into the file (see the header comment). Checks as writeWalkerHtml
// (Error(BadArgument) "HTML walker: …", no file named).
HtmlCanvasMapping htmlCanvasMapping(const HtmlWalker& walker, const HtmlWalkerSettings& settings);

// Where the page draws the 15 dots at τ = timeS seconds after it started, with its controls
// untouched: 15 × 2 (X, Y) in CSS pixels of the canvas, joint order of METHOD §1. The
// page's first frame is timeS = 0. Error(BadArgument) for a bad walker, settings or a
// non-finite time.
Eigen::MatrixXd htmlWalkerDotsPx(const HtmlWalker& walker, const HtmlWalkerSettings& settings,
                                 double timeS);

// [SECTION] The file

// The page as text (what writeWalkerHtml writes). Every number the page computes with is
// written with 17 significant digits (doubles round-trip exactly). `file` is only named in
// errors.
std::string walkerHtml(const HtmlWalker& walker, const HtmlWalkerSettings& settings,
                       const std::string& file = "");

// Writes walkerHtml to `path` atomically (core/io/atomic_write.h). Refuses, with
// Error(BadArgument) naming `path` and reading "HTML walker: …": w not 225 finite values,
// ω not positive and finite, φ not finite, and every setting outside the ranges above
// (non-finite numbers, a colour other than #rrggbb, a title or caption too long or holding
// control characters). Error(Io) when the file cannot be written.
void writeWalkerHtml(const std::filesystem::path& path, const HtmlWalker& walker,
                     const HtmlWalkerSettings& settings);

// The page's address to show the frame at τ = timeS and stay paused there: "#t=<timeS>"
// appended to a file: URL. The page reads it on load (a screenshot, a handout's still).
std::string htmlFrozenFragment(double timeS);

}  // namespace ew
