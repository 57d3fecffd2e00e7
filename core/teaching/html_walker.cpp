#include "core/teaching/html_walker.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"
#include "core/io/atomic_write.h"

namespace ew {
namespace {

// [SECTION] Checks

constexpr int kCycleSamples = 360;          // samples of θ over which the Fit framing is measured
constexpr double kFitMarginShare = 0.05;    // of the canvas's smaller side, beside the dot radius

[[noreturn]] void refuse(const std::string& file, const std::string& problem) {
  throw Error(ErrorKind::BadArgument, file, "", "HTML walker: " + problem);
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void requireIn(double v, double lo, double hi, const std::string& what, const std::string& file) {
  if (!(std::isfinite(v) && v >= lo && v <= hi))
    refuse(file, what + " must be in [" + number(lo) + ", " + number(hi) + "], got " + number(v));
}

bool isHexColour(const std::string& c) {
  return c.size() == 7 && c[0] == '#' && std::all_of(c.begin() + 1, c.end(), [](char ch) {
           return std::isxdigit(static_cast<unsigned char>(ch));
         });
}

void requireText(const std::string& text, std::size_t maxBytes, bool newlines,
                 const std::string& what, const std::string& file) {
  if (text.size() > maxBytes)
    refuse(file, what + " is " + std::to_string(text.size()) + " bytes, at most " +
                     std::to_string(maxBytes));
  for (char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if ((c < 0x20 && !(newlines && c == '\n')) || c == 0x7f)
      refuse(file, what + " holds a control character (code " + std::to_string(c) + ")");
  }
}

void checkInputs(const HtmlWalker& walker, const HtmlWalkerSettings& s, const std::string& file) {
  if (walker.w.size() != kFourierDims3)
    refuse(file, "the walker's Fourier vector must have 225 values (METHOD §3), got " +
                     std::to_string(walker.w.size()));
  if (!walker.w.allFinite()) refuse(file, "the walker's Fourier vector has non-finite values");
  if (!(std::isfinite(walker.omegaRadS) && walker.omegaRadS > 0.0))
    refuse(file, "ω must be positive and finite, got " + number(walker.omegaRadS) + " rad/s");
  if (!std::isfinite(walker.phaseRad))
    refuse(file, "φ must be finite, got " + number(walker.phaseRad));
  requireText(walker.name, 200, false, "the walker's name", file);
  if (!std::isfinite(s.viewAngleDeg))
    refuse(file, "the view angle must be finite, got " + number(s.viewAngleDeg));
  requireIn(s.elevationDeg, -90.0, 90.0, "the elevation (degrees)", file);
  requireIn(s.playbackSpeed, -5.0, 5.0, "the playback speed", file);
  if (!std::isfinite(s.startPhase01))
    refuse(file, "the start phase must be finite, got " + number(s.startPhase01));
  requireIn(s.translateSpeedMps, 0.0, 10.0, "the translation speed (m/s)", file);
  requireIn(s.widthPx, 64, 4096, "the canvas width (px)", file);
  requireIn(s.heightPx, 64, 4096, "the canvas height (px)", file);
  if (!(std::isfinite(s.dotRadiusPx) && s.dotRadiusPx > 0.0 && s.dotRadiusPx <= 50.0))
    refuse(file, "the dot radius must be in (0, 50] px, got " + number(s.dotRadiusPx));
  const double margin = s.dotRadiusPx + kFitMarginShare * std::min(s.widthPx, s.heightPx);
  if (2.0 * margin >= 0.5 * std::min(s.widthPx, s.heightPx))
    refuse(file, "dots of radius " + number(s.dotRadiusPx) +
                     " px leave the walker too little room on a " + std::to_string(s.widthPx) +
                     " × " + std::to_string(s.heightPx) + " canvas");
  for (const auto& [c, what] : {std::pair{&s.dotColour, "the dot colour"},
                                std::pair{&s.backgroundColour, "the background colour"}})
    if (!c->empty() && !isHexColour(*c))
      refuse(file, std::string(what) + " must be #rrggbb, got \"" + *c + "\"");
  requireText(s.title, 200, false, "the title", file);
  requireText(s.caption, 2000, true, "the caption", file);
}

// [SECTION] Geometry shared by the mapping and the dots

struct Extent {
  double radiusMm = 0.0;  // R: the largest √(x² + y²)
  double vLoMm = 0.0, vHiMm = 0.0;
};

Extent cycleExtent(const HtmlWalker& walker, double elevationDeg) {
  const Eigen::VectorXd theta = Eigen::VectorXd::LinSpaced(
      kCycleSamples, 0.0, 2.0 * std::numbers::pi * (kCycleSamples - 1) / kCycleSamples);
  const Eigen::MatrixXd frames = synthesizeFrames(walker.w, 1.0, 0.0, theta);
  const double e = degToRad(elevationDeg), ce = std::cos(e), se = std::abs(std::sin(e));
  Extent x{0.0, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (Eigen::Index i = 0; i < frames.rows(); ++i)
    for (int j = 0; j < kJointCount; ++j) {
      const double rho = std::hypot(frames(i, 3 * j), frames(i, 3 * j + 1)),
                   z = frames(i, 3 * j + 2);
      x.radiusMm = std::max(x.radiusMm, rho);
      x.vLoMm = std::min(x.vLoMm, z * ce - rho * se);
      x.vHiMm = std::max(x.vHiMm, z * ce + rho * se);
    }
  return x;
}

HtmlCanvasMapping mappingOf(const HtmlWalker& walker, const HtmlWalkerSettings& s,
                            const std::string& file) {
  const Extent x = cycleExtent(walker, s.elevationDeg);
  if (!(x.radiusMm > 0.0 && x.vHiMm > x.vLoMm))
    refuse(file, "the walker has no extent to draw (all joints at one point)");
  const double width = s.widthPx, height = s.heightPx;
  HtmlCanvasMapping m;
  m.centreXPx = 0.5 * width;
  if (s.framing == HtmlFraming::Viewer) {
    m.pxPerMm = height / kViewerViewHeightMm;
    m.centreYPx = 0.5 * height + kViewerViewCentreVMm * m.pxPerMm;
  } else {
    const double margin = s.dotRadiusPx + kFitMarginShare * std::min(width, height);
    m.pxPerMm = std::min((width - 2.0 * margin) / (2.0 * x.radiusMm),
                         (height - 2.0 * margin) / (x.vHiMm - x.vLoMm));
    m.centreYPx = 0.5 * height + m.pxPerMm * 0.5 * (x.vHiMm + x.vLoMm);
  }
  m.wrapXPx = width + 2.0 * x.radiusMm * m.pxPerMm;
  m.wrapYPx = height + (x.vHiMm - x.vLoMm) * m.pxPerMm;
  return m;
}

// o ↦ ((o + P/2) mod P) − P/2, the page's `wrap`.
double wrapOffset(double o, double period) { return o - period * std::floor(o / period + 0.5); }

// [SECTION] The page

HtmlColours themeColours(HtmlTheme theme) {
  switch (theme) {
    case HtmlTheme::Light:
      return {"#ffffff", "#111111", "#a0a6ae", "#222222"};
    case HtmlTheme::Projector:
      return {"#000000", "#ffffff", "#8c8c8c", "#ffffff"};
    case HtmlTheme::Dark:
      break;
  }
  return {"#101216", "#ffffff", "#5c6370", "#d8dde6"};
}

std::string escapeHtml(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      case '\n':
        out += "<br>";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

std::string jsArray(const Eigen::VectorXd& v) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (i > 0) out += (i % 9 == 0) ? ",\n  " : ",";
    out += number(v(i));
  }
  return out + "]";
}

std::string bonesArray() {
  std::string out = "[";
  for (const auto& [a, b] : kBones)
    out += (out.size() > 1 ? "," : "") + std::string("[") + std::to_string(index(a)) + "," +
           std::to_string(index(b)) + "]";
  return out + "]";
}

// The script: the walker, the settings and the mapping as numbers, then the same p(t), view
// and mapping as htmlWalkerDotsPx (see the header).
constexpr const char* kScript = R"JS(
const canvas = document.getElementById("stage");
const ctx = canvas.getContext("2d");
const ratio = window.devicePixelRatio || 1;
canvas.width = Math.round(S.width * ratio);
canvas.height = Math.round(S.height * ratio);
ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
const T0 = (2 * Math.PI * S.startPhase01 - PHI) / OMEGA;  // theta = 2 pi startPhase01 at tau = 0

// p(t): p0 + p1 sin(wt+phi) + q1 cos(wt+phi) + p2 sin 2(wt+phi) + q2 cos 2(wt+phi), 45 values.
function posture(t) {
  const th = OMEGA * t + PHI, s = Math.sin(th), c = Math.cos(th);
  const b = [1, s, c, 2 * s * c, c * c - s * s];
  const p = new Float64Array(45);
  for (let k = 0; k < 45; k++) {
    let v = 0;
    for (let h = 0; h < 5; h++) v += b[h] * W[45 * h + k];
    p[k] = v;
  }
  return p;
}
function wrap(o, period) { return o - period * Math.floor(o / period + 0.5); }
// The 15 dots in canvas pixels at walker time tw (s) seen at alphaDeg.
function dots(tw, alphaDeg) {
  const p = posture(T0 + tw);
  const a = alphaDeg * (Math.PI / 180), ca = Math.cos(a), sa = Math.sin(a);
  const e = S.elevationDeg * (Math.PI / 180), ce = Math.cos(e), se = Math.sin(e);
  const dy = S.translate ? 1000 * S.translateSpeedMps * tw : 0;
  const ox = wrap(M.pxPerMm * dy * sa, M.wrapXPx), oy = wrap(-M.pxPerMm * dy * se * ca, M.wrapYPx);
  const out = [];
  for (let j = 0; j < 15; j++) {
    const x = p[3 * j], y = p[3 * j + 1], z = p[3 * j + 2];
    const u = ca * x + sa * y, d = -sa * x + ca * y, v = z * ce + d * se;
    out.push([M.centreXPx + M.pxPerMm * u + ox, M.centreYPx - M.pxPerMm * v + oy]);
  }
  return out;
}

const state = {tw: 0, alphaDeg: S.viewAngleDeg, speed: S.playbackSpeed, lines: S.lines,
               playing: true, last: null};
const frozen = /^#t=([-+0-9.eE]+)$/.exec(window.location.hash);
if (frozen && isFinite(Number(frozen[1]))) {
  state.tw = S.playbackSpeed * Number(frozen[1]);
  state.playing = false;
}
function draw() {
  ctx.fillStyle = C.background;
  ctx.fillRect(0, 0, S.width, S.height);
  const q = dots(state.tw, state.alphaDeg);
  if (state.lines) {
    ctx.strokeStyle = C.line;
    ctx.lineWidth = Math.max(1, 0.6 * S.dotRadiusPx);
    ctx.lineCap = "round";
    ctx.beginPath();
    for (const [a, b] of BONES) { ctx.moveTo(q[a][0], q[a][1]); ctx.lineTo(q[b][0], q[b][1]); }
    ctx.stroke();
  }
  ctx.fillStyle = C.dot;
  for (const [x, y] of q) {
    ctx.beginPath();
    ctx.arc(x, y, S.dotRadiusPx, 0, 2 * Math.PI);
    ctx.fill();
  }
}
function tick(now) {
  if (!state.playing) return;
  if (state.last !== null) state.tw += state.speed * (now - state.last) / 1000;
  state.last = now;
  draw();
  window.requestAnimationFrame(tick);
}

// The controls: they change what is drawn next, never the mapping or the first frame.
const play = document.getElementById("play");
const alpha = document.getElementById("alpha"), alphaText = document.getElementById("alphaText");
const speed = document.getElementById("speed"), speedText = document.getElementById("speedText");
const lines = document.getElementById("lines");
function label() {
  play.textContent = state.playing ? "Pause" : "Play";
  alphaText.textContent = state.alphaDeg.toFixed(0) + "\u00b0";
  speedText.textContent = state.speed.toFixed(2) + "\u00d7";
}
play.addEventListener("click", () => {
  state.playing = !state.playing;
  state.last = null;
  label();
  if (state.playing) window.requestAnimationFrame(tick);
});
alpha.addEventListener("input", () => { state.alphaDeg = Number(alpha.value); label(); draw(); });
speed.addEventListener("input", () => { state.speed = Number(speed.value); label(); });
lines.addEventListener("change", () => { state.lines = lines.checked; draw(); });
document.addEventListener("keydown", (e) => { if (e.key === " " && e.target === document.body) { e.preventDefault(); play.click(); } });
label();
draw();
if (state.playing) window.requestAnimationFrame(tick);
)JS";

}  // namespace

HtmlColours htmlColours(const HtmlWalkerSettings& settings) {
  HtmlColours c = themeColours(settings.theme);
  if (!settings.dotColour.empty()) c.dot = settings.dotColour;
  if (!settings.backgroundColour.empty()) c.background = settings.backgroundColour;
  return c;
}

HtmlCanvasMapping htmlCanvasMapping(const HtmlWalker& walker, const HtmlWalkerSettings& settings) {
  checkInputs(walker, settings, "");
  return mappingOf(walker, settings, "");
}

Eigen::MatrixXd htmlWalkerDotsPx(const HtmlWalker& walker, const HtmlWalkerSettings& s,
                                 double timeS) {
  checkInputs(walker, s, "");
  if (!std::isfinite(timeS)) refuse("", "the time must be finite, got " + number(timeS));
  const HtmlCanvasMapping m = mappingOf(walker, s, "");
  const double t0 = (2.0 * std::numbers::pi * s.startPhase01 - walker.phaseRad) / walker.omegaRadS;
  const double tw = s.playbackSpeed * timeS;
  Eigen::VectorXd t(1);
  t(0) = t0 + tw;
  const Eigen::MatrixXd p = synthesizeFrames(walker.w, walker.omegaRadS, walker.phaseRad, t);
  const double a = degToRad(s.viewAngleDeg), ca = std::cos(a), sa = std::sin(a);
  const double e = degToRad(s.elevationDeg), ce = std::cos(e), se = std::sin(e);
  const double dy = s.translate ? 1000.0 * s.translateSpeedMps * tw : 0.0;
  const double ox = wrapOffset(m.pxPerMm * dy * sa, m.wrapXPx),
               oy = wrapOffset(-m.pxPerMm * dy * se * ca, m.wrapYPx);
  Eigen::MatrixXd out(kJointCount, 2);
  for (int j = 0; j < kJointCount; ++j) {
    const double x = p(0, 3 * j), y = p(0, 3 * j + 1), z = p(0, 3 * j + 2);
    const double u = ca * x + sa * y, d = -sa * x + ca * y, v = z * ce + d * se;
    out(j, 0) = m.centreXPx + m.pxPerMm * u + ox;
    out(j, 1) = m.centreYPx - m.pxPerMm * v + oy;
  }
  return out;
}

std::string walkerHtml(const HtmlWalker& walker, const HtmlWalkerSettings& s,
                       const std::string& file) {
  checkInputs(walker, s, file);
  const HtmlCanvasMapping m = mappingOf(walker, s, file);
  const HtmlColours c = htmlColours(s);
  const std::string width = std::to_string(s.widthPx), height = std::to_string(s.heightPx);
  const std::string framing =
      s.framing == HtmlFraming::Viewer
          ? "the viewer's 2D view: 2350 mm of height across the canvas, v = 975 mm at its centre "
            "row"
          : "fitted: the walker over one cycle, seen from every view angle, fits the canvas";
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    // Nothing is fetched: no other source, no connection; only this file's own script and style.
    << "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
       "script-src 'unsafe-inline'; style-src 'unsafe-inline'\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<meta name=\"generator\" content=\"Eigenwalker (core/teaching/html_walker.h)\">\n"
    << "<title>" << escapeHtml(s.title) << "</title>\n<style>\n"
    << "html, body { margin: 0; padding: 0; background: " << c.background << "; color: " << c.text
    << "; font: 15px/1.45 sans-serif; }\n"
    << "canvas { display: block; width: " << width << "px; height: " << height << "px; }\n"
    << "main { max-width: " << std::max(s.widthPx, 480)
    << "px; padding: 10px 14px; box-sizing: border-box; }\n"
    << "h1 { font-size: 20px; margin: 4px 0; } button { min-width: 5em; }\n"
    << "label { margin-right: 14px; white-space: nowrap; } input[type=range] { vertical-align: "
       "middle; }\n"
    << "details { margin-top: 10px; } code { font-size: 13px; }\n</style>\n</head>\n<body>\n"
    << "<canvas id=\"stage\" width=\"" << width << "\" height=\"" << height
    << "\" aria-label=\"A point-light walker\"></canvas>\n"
    << "<main>\n<h1>" << escapeHtml(s.title) << "</h1>\n";
  if (!s.caption.empty()) h << "<p>" << escapeHtml(s.caption) << "</p>\n";
  if (!walker.name.empty()) h << "<p>Walker: " << escapeHtml(walker.name) << ".</p>\n";
  h << "<p>\n<button id=\"play\" type=\"button\">Pause</button>\n"
    << "<label>view angle <input id=\"alpha\" type=\"range\" min=\"-180\" max=\"180\" step=\"1\" "
       "value=\""
    << number(wrapDeg(s.viewAngleDeg)) << "\"> <span id=\"alphaText\"></span></label>\n"
    << "<label>speed <input id=\"speed\" type=\"range\" min=\"-5\" max=\"5\" step=\"0.05\" value=\""
    << number(s.playbackSpeed) << "\"> <span id=\"speedText\"></span></label>\n"
    << "<label><input id=\"lines\" type=\"checkbox\"" << (s.lines ? " checked" : "")
    << "> lines</label>\n</p>\n"
    << "<details>\n<summary>How this page draws the walker</summary>\n"
    << "<p>Each dot is one of 15 joints (head, sternum, pelvis, shoulders, elbows, wrists, hips, "
       "knees, "
       "ankles). Its path over a gait cycle is a mean posture plus two harmonics, "
       "p(t) = p0 + p1 sin(&omega;t+&phi;) + q1 cos(&omega;t+&phi;) + p2 sin 2(&omega;t+&phi;) + "
       "q2 cos 2(&omega;t+&phi;), in millimetres: x to the walker's right, y forward, z up; "
       "&omega; = "
    << number(walker.omegaRadS) << " rad/s (" << number(walker.omegaRadS / (2.0 * std::numbers::pi))
    << " strides per second).</p>\n"
    << "<p>The camera is orthographic at view angle &alpha; (0&deg; from behind, 90&deg; the "
       "walker's right side) "
       "and elevation &epsilon; = "
    << number(s.elevationDeg)
    << "&deg;: u = x cos &alpha; + y sin &alpha;, "
       "v = z cos &epsilon; + (&minus;x sin &alpha; + y cos &alpha;) sin &epsilon;.</p>\n"
    << "<p>Millimetres to canvas pixels (" << framing << "; the controls never change it): "
    << "X = <code>" << number(m.centreXPx) << "</code> + <code>" << number(m.pxPerMm)
    << "</code> &middot; u, "
    << "Y = <code>" << number(m.centreYPx) << "</code> &minus; <code>" << number(m.pxPerMm)
    << "</code> &middot; v, in CSS pixels from the canvas's top-left corner"
    << (s.translate ? "; walking overground, the progression wraps every " + number(m.wrapXPx) +
                          " px across"
                    : "")
    << ". Add <code>#t=1.5</code> to this page's address to hold the frame 1.5 s after the "
       "start.</p>\n"
    << "<p>Made with Eigenwalker (Zhang &amp; Troje 2007; Troje 2002).</p>\n</details>\n</main>\n"
    << "<script>\n\"use strict\";\n"
    << "// The walker: w = [p0, p1, q1, p2, q2] (225 values, mm; block, joint, x y z), omega "
       "(rad/s), phi (rad).\n"
    << "const W = " << jsArray(walker.w) << ";\n"
    << "const OMEGA = " << number(walker.omegaRadS) << ", PHI = " << number(walker.phaseRad)
    << ";\n"
    << "const BONES = " << bonesArray() << ";\n"
    << "const S = {width: " << width << ", height: " << height
    << ", viewAngleDeg: " << number(s.viewAngleDeg) << ", elevationDeg: " << number(s.elevationDeg)
    << ", playbackSpeed: " << number(s.playbackSpeed)
    << ", startPhase01: " << number(s.startPhase01) << ", lines: " << (s.lines ? "true" : "false")
    << ", translate: " << (s.translate ? "true" : "false")
    << ", translateSpeedMps: " << number(s.translateSpeedMps)
    << ", dotRadiusPx: " << number(s.dotRadiusPx) << "};\n"
    << "// mm -> canvas pixels: X = centreXPx + pxPerMm u, Y = centreYPx - pxPerMm v; wraps of the "
       "progression.\n"
    << "const M = {pxPerMm: " << number(m.pxPerMm) << ", centreXPx: " << number(m.centreXPx)
    << ", centreYPx: " << number(m.centreYPx) << ", wrapXPx: " << number(m.wrapXPx)
    << ", wrapYPx: " << number(m.wrapYPx) << "};\n"
    << "const C = {background: \"" << c.background << "\", dot: \"" << c.dot << "\", line: \""
    << c.line << "\"};\n"
    << kScript << "</script>\n</body>\n</html>\n";
  return h.str();
}

void writeWalkerHtml(const std::filesystem::path& path, const HtmlWalker& walker,
                     const HtmlWalkerSettings& settings) {
  const std::string page = walkerHtml(walker, settings, path.string());
  writeFileAtomically(path, [&](std::ostream& out) { out << page; });
}

std::string htmlFrozenFragment(double timeS) {
  if (!std::isfinite(timeS)) refuse("", "the frozen time must be finite, got " + number(timeS));
  return "#t=" + number(timeS);
}

}  // namespace ew
