#pragma once
// A whole 2D sequence through the snippet engine (Howe, Leventon & Freeman 1999, §3–4.1):
// resampled to the prior's rate, cut into overlapping snippets (every `hop` frames), each
// reconstructed by MAP (snippet_fit.h), stitched by weighted interpolation where they
// overlap (triangular weights, largest at a snippet's middle frame), then resampled back
// to the input's frames.
//
// Stitching happens in the view's frame: U along the image's horizontal, D the depth
// (away from the camera), V up, in mm at the walker (image ÷ scale). The image fixes U
// and V; each snippet's depth is free up to a rigid slip along the line of sight, which
// the paper corrects with ground contact. Here each snippet k gets a depth offset δ_k and
// a depth drift γ_k (mm per frame), found by least squares from (a) agreement of
// overlapping snippets, (b) a stance foot does not slide: the lower ankle, while its image
// speed is below 20 % of the clip's 95th-percentile ankle speed, keeps its depth from one
// frame to the next, and (c) Σ δ_k = 0, a small ridge on γ. The output is turned back
// from the view by the clip's angle α̂ into the walker's frame of METHOD §2 (x right,
// y forward, z up), mm.

#include <Eigen/Core>
#include <vector>

#include "core/snippet/snippet_fit.h"

namespace ew {

// The angle among `anglesDeg` with the least summed wrapped distance to the others; where
// several tie (the middle two of an even count), their circular mean, as a median of an even
// count is its middle two's mean.
double circularMedianDeg(const std::vector<double>& anglesDeg);

struct SnippetSequenceOptions {
  SnippetFitOptions fit;
  int hop = 4;                  // frames between snippet starts, at the prior's rate
  bool groundContact = false;   // off by default: measured to hurt (docs/SNIPPETS.md)
  // Unknown view: every snippet is first fitted over the whole circle; the clip's α̂ is the
  // circular median of their angles, then every snippet is refitted with α started there
  // and free within ±localWindowDeg (a walker's heading changes slowly).
  double localWindowDeg = 15.0;
};

struct SnippetSequence {
  Eigen::MatrixXd framesMm;     // T × 45 at the input's frames, walker's frame (above)
  double alphaDeg = 0.0;        // the clip's view angle (known, or α̂)
  double scale = 1.0;           // median scale of the snippets
  double rateHz = 0.0;          // the prior's rate, at which snippets were fitted
  std::vector<int> starts;      // first frame of each snippet (prior's rate)
  std::vector<SnippetFit> snippets;
  std::vector<double> freeAlphaDeg;  // unknown view: each snippet's own α over the circle
  int stanceConstraints = 0;    // frame pairs held by ground contact
  double reprojectionRms = 0.0; // image units, mean over the snippets
};

// uv: T × 30 (u, v per joint and frame, v up; NaN = not seen) at `rateHz`. Needs at least
// one snippet's span (S frames at the prior's rate; Error(BadData) "snippets: …" naming
// the length otherwise). Throws Error(BadArgument) for a wrong shape or a bad rate.
SnippetSequence reconstructSnippetSequence(const PreparedSnippetPrior& prior,
                                           const Eigen::Ref<const Eigen::MatrixXd>& uv, double rateHz,
                                           const SnippetSequenceOptions& options = {});

}  // namespace ew
