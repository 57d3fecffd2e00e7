#include "core/camera/known_stature.h"

#include <cmath>
#include <sstream>

#include "core/common/errors.h"

namespace ew {

void scaleToStature(ClipReconstruction& clip, double statureMm) {
  if (!(statureMm >= 1000.0 * kMinStatureM && statureMm <= 1000.0 * kMaxStatureM)) {
    std::ostringstream problem;
    problem << "stature: " << statureMm / 1000.0 << " m is not a person's (" << kMinStatureM << "-" << kMaxStatureM
            << " m)";
    throw Error(ErrorKind::BadArgument, clip.trial.file, "", problem.str());
  }
  CameraFit& fit = clip.fit;
  if (!(fit.statureMm > 0.0) || !std::isfinite(fit.statureMm))
    throw Error(ErrorKind::BadArgument, clip.trial.file, "", "stature: the fit has no stature to scale");
  const double s = statureMm / fit.statureMm;
  fit.w *= s;
  clip.framesMm *= s;
  clip.feet.feetMm *= s;  // each lifted point lies on its ray, s times further along it
  WalkCamera& c = fit.camera;
  c.distanceMm *= s;
  c.lookAtHeightMm *= s;
  c.startOffsetMm *= s;
  c.speedMmS *= s;
  c.pxPerMm /= s;
  fit.headHeightMm *= s;
  fit.statureMm = statureMm;
  fit.speedMps *= s;
  fit.strideLengthM *= s;
  fit.sd.statureMm = 0.0;
  fit.sd.speedMps = fit.sd.speedShareGivenStature * fit.speedMps;
  fit.sd.strideLengthM = fit.sd.strideShareGivenStature * fit.strideLengthM;
  fit.walkerDistanceM *= s;
  fit.walkerDistanceFirstM *= s;
  fit.walkerDistanceLastM *= s;
  fit.sd.walkerDistanceM = fit.sd.walkerDistanceShareGivenStature * fit.walkerDistanceM;
  for (CameraStart& start : fit.starts) start.speedMmS *= s;
}

void scaleToStature(DetectionLoop& loop, double statureMm) {
  scaleToStature(loop.first, statureMm);
  scaleToStature(loop.last, statureMm);
}

}  // namespace ew
