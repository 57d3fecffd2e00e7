#include "ui/app/export.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>
#include <system_error>

#include "core/eigenwalker/fourier.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/export_captions.h"
#include "ui/app/video.h"
#include "ui/panels/clip_view.h"
#include "ui/panels/input_view_panel.h"
#include "ui/panels/reconstruction_view_panel.h"
#include "ui/panels/video_view.h"
#include "ui/render/camera.h"
#include "ui/render/renderer.h"

namespace ew::ui {

// [SECTION] Walker in the time domain

WalkerMotion displayedWalkerMotion(const AppState& s, std::optional<double> cycles, double rateHz) {
  const Eigen::VectorXd* w = nullptr;
  double strideHz = 0.0;
  double defaultCycles = 4.0;
  WalkerMotion m;
  if (s.doc.mode == Mode::Clip) {
    if (!s.clip.fit()) throw std::invalid_argument("no keypoint clip fitted yet");
    const CameraFit& fit = s.clip.fit()->rec.fit;
    w = &fit.w;
    strideHz = fit.strideHz;
    defaultCycles = std::max(1.0, s.clip.fit()->rec.gait.cycles);
    m.description = "reconstruction of the keypoint clip " + s.clip.fit()->settings.path.string() + " through its camera (azimuth " +
                    std::to_string(fit.camera.alphaDeg) + " deg, elevation " + std::to_string(fit.camera.elevationDeg) +
                    " deg), model " + s.clip.fit()->model.name;
  } else if (s.doc.mode == Mode::Reconstruct) {
    const auto* r = s.derived.recon();
    const auto* d = s.derived.display();
    if (!r || !d) throw std::invalid_argument("no reconstruction to export yet");
    w = &d->w;
    strideHz = r->strideHz;
    const Walker* walker = s.doc.selectedWalker();
    if (!walker) throw std::invalid_argument("no walker selected");
    defaultCycles = std::max(1.0, walker->fit.cycles);
    m.description = "reconstruction of " + walker->id + " (" +
                    (s.doc.recon.estimator == Estimator::Lsq ? "LSQ" : "MAP") + ", model " +
                    (r->inModel ? r->modelName + " without " + r->heldOutSubject : r->modelName) +
                    ", N = " + std::to_string(r->components) +
                    (d->edited ? ", coefficients edited" : "") + ")";
  } else {
    const auto* e = s.derived.explore();
    if (!e) throw std::invalid_argument("no walker to export yet");
    w = &e->w;
    strideHz = e->strideHz;
    m.description = "walker synthesised from " + std::to_string(e->components) + " eigenwalker coefficients";
  }
  const double n = cycles.value_or(defaultCycles);
  if (!std::isfinite(n) || n <= 0.0 || n > 1000.0) throw std::invalid_argument("cycles must lie in (0, 1000]");
  if (!(rateHz > 0.0)) throw std::invalid_argument("rate must be positive");
  if (!(strideHz > 0.0 && std::isfinite(strideHz))) throw std::invalid_argument("the walker has no stride frequency");
  const int frames = std::max(2, static_cast<int>(std::lround(n / strideHz * rateHz)));
  m.framesX45 = synthesizeFrames(*w, 2.0 * std::numbers::pi * strideHz, 0.0, frameTimes(frames, rateHz));
  m.rateHz = rateHz;
  m.cycles = n;
  return m;
}

// [SECTION] Video

int videoFrameCount(double cycles, double fps, double strideHz) {
  return std::max(1, static_cast<int>(std::lround(cycles * fps / strideHz)));
}

struct VideoExport::Impl {
  VideoSettings settings;
  double strideHz = 0.0;
  std::filesystem::path temp;
  cv::VideoWriter writer;
  gl::RenderTarget left, right;
  std::optional<CaptionPainter> captions;
  std::optional<VideoSource> footage;  // a tracked video's frames, decoded in order
  Scene scene;
  cv::Mat frame;  // BGR, width × height
  int total = 0, done = 0;
  bool finished = false;
  double seconds = 0.0;  // spent in step()
};

namespace {

std::string lowerExtension(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// GL rows (bottom first, RGB) into a BGR image region (top first).
void blitRgb(const std::vector<unsigned char>& rgb, int w, int h, cv::Mat& dst, int x0) {
  const cv::Mat src(h, w, CV_8UC3, const_cast<unsigned char*>(rgb.data()));
  cv::Mat flipped;
  cv::flip(src, flipped, 0);
  cv::cvtColor(flipped, dst(cv::Rect(x0, 0, w, h)), cv::COLOR_RGB2BGR);
}

// The left half as the 2D view shows a tracked video: the frame at the video's aspect, the
// tracked joints and the walker drawn back over it (ui/panels/video_view.h).
void renderFootage(std::optional<VideoSource>& footage, gl::RenderTarget& target, Scene& scene, const AppState& s,
                   Renderer& renderer, float lineScale, int videoFrame, float aspect) {
  if (!footage) footage.emplace(s.video.session->path);
  const cv::Mat picture = footage->frame(videoFrame);
  const VideoInfo& info = footage->info();
  const VideoViewFrame view = videoViewFrame(info.widthPx, info.heightPx, aspect);
  buildVideoInputScene(s, scene, lineScale, view.heightPx / static_cast<float>(target.height()), videoFrame, &picture);
  renderer.render(target, scene, imageCamera(aspect, view.centre, view.heightPx));
}

}  // namespace

VideoExport::VideoExport(const VideoSettings& settings, double strideHz) : impl_(std::make_unique<Impl>()) {
  auto& m = *impl_;
  m.settings = settings;
  m.strideHz = strideHz;
  const auto& v = settings;
  if (v.path.empty()) throw std::invalid_argument("video: no file name");
  if (!std::isfinite(v.cycles) || v.cycles <= 0.0 || v.cycles > 200.0)
    throw std::invalid_argument("video: cycles must lie in (0, 200]");
  if (!std::isfinite(v.fps) || v.fps < 1.0 || v.fps > 240.0) throw std::invalid_argument("video: fps must lie in [1, 240]");
  if (v.width < 64 || v.height < 64 || v.width > 7680 || v.height > 4320 || v.width % 2 || v.height % 2)
    throw std::invalid_argument("video: width and height must be even, 64…7680 × 64…4320");
  if (!(strideHz > 0.0)) throw std::invalid_argument("video: the walker has no stride frequency");
  const std::string ext = lowerExtension(v.path);
  int fourcc = 0;
  if (ext == ".avi") {
    fourcc = cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
  } else if (ext == ".mp4") {
    fourcc = cv::VideoWriter::fourcc('m', 'p', '4', 'v');
  } else {
    throw std::invalid_argument("video: " + v.path.string() + ": the file name must end in .avi (MJPG) or .mp4 (mp4v)");
  }
  std::error_code ec;
  if (v.path.has_parent_path()) std::filesystem::create_directories(v.path.parent_path(), ec);
  m.temp = v.path.parent_path() / ("." + v.path.stem().string() + ".tmp-" + std::to_string(::getpid()) + ext);
  try {
    m.writer.open(m.temp.string(), fourcc, v.fps, cv::Size(v.width, v.height), true);
  } catch (const cv::Exception& e) {
    throw std::runtime_error("video: " + v.path.string() + ": OpenCV cannot open the writer: " + e.what());
  }
  if (!m.writer.isOpened()) {
    std::filesystem::remove(m.temp, ec);
    if (ext == ".mp4")
      throw std::runtime_error("video: " + v.path.string() +
                               ": this OpenCV build cannot write .mp4 with the mp4v codec; export .avi (MJPG) instead");
    throw std::runtime_error("video: " + v.path.string() + ": cannot open the video writer (is the folder writable?)");
  }
  m.total = videoFrameCount(v.cycles, v.fps, strideHz);
  m.frame.create(v.height, v.width, CV_8UC3);
  if (v.captions) {
    try {
      m.captions.emplace();
    } catch (const std::exception&) {
      m.writer.release();
      std::filesystem::remove(m.temp, ec);
      throw;
    }
  }
}

VideoExport::~VideoExport() {
  if (!impl_->finished) {
    impl_->writer.release();
    std::error_code ec;
    std::filesystem::remove(impl_->temp, ec);
  }
}

bool VideoExport::step(const AppState& s, Renderer& renderer, double budgetMs) {
  auto& m = *impl_;
  if (m.finished) return true;
  const auto start = std::chrono::steady_clock::now();
  const int wl = m.settings.width / 2, wr = m.settings.width - wl, h = m.settings.height;
  const float lineScale = std::max(1.0f, static_cast<float>(h) / 720.0f);
  m.left.ensure(wl, h, renderer.samples());
  m.right.ensure(wr, h, renderer.samples());
  while (m.done < m.total) {
    const double cycles = static_cast<double>(m.done) * m.strideHz / m.settings.fps;
    const float aspectLeft = static_cast<float>(wl) / static_cast<float>(h);
    int frame = 0;
    if (s.doc.mode == Mode::Clip && s.clip.fit()) {
      // A keypoint clip: its input frames in image pixels, the walker where the camera saw it
      // (over the footage, for a tracked video).
      frame = clipFrameAt(*s.clip.fit(), cycles);
      if (const auto fit = actions::videoFitFrames(s)) {  // its footage goes under it
        renderFootage(m.footage, m.left, m.scene, s, renderer, lineScale, fit->first + frame, aspectLeft);
      } else {
        const ClipImageFrame image = clipImageFrame(*s.clip.fit(), aspectLeft);
        buildClipInputScene(s, m.scene, lineScale, frame, image);
        renderer.render(m.left, m.scene, clipInputCamera(image, aspectLeft));
      }
      buildClipReconstructionScene(s, m.scene, lineScale, frame);
      renderer.render(m.right, m.scene,
                      clipViewCamera(s.view.camera, *s.clip.fit(), frame).matrices(static_cast<float>(wr) / static_cast<float>(h)));
    } else {
      buildInputScene(s, m.scene, lineScale, cycles - std::floor(cycles));
      renderer.render(m.left, m.scene, inputViewCamera(aspectLeft));
      float errorScale = 1.0f;
      buildReconstructionScene(s, m.scene, lineScale, cycles, &errorScale);
      renderer.render(m.right, m.scene, s.view.camera.matrices(static_cast<float>(wr) / static_cast<float>(h)));
    }
    blitRgb(m.left.readPixelsRgb(), wl, h, m.frame, 0);
    blitRgb(m.right.readPixelsRgb(), wr, h, m.frame, wl);
    if (m.captions) {
      cv::Mat left = m.frame(cv::Rect(0, 0, wl, h)), right = m.frame(cv::Rect(wl, 0, wr, h));
      m.captions->paint(left, inputCaption(s, frame), {});
      m.captions->paint(right, reconstructionCaption(s), s.view.overlays.metrics ? metricItems(s) : std::vector<MetricItem>{});
    }
    try {
      m.writer.write(m.frame);
    } catch (const cv::Exception& e) {
      throw std::runtime_error("video: " + m.settings.path.string() + ": encoding failed: " + e.what());
    }
    ++m.done;
    if (std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() > budgetMs) break;
  }
  m.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (m.done < m.total) return false;
  const auto closeStart = std::chrono::steady_clock::now();
  m.writer.release();
  m.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - closeStart).count();
  std::error_code ec;
  std::filesystem::rename(m.temp, m.settings.path, ec);
  if (ec) throw std::runtime_error("video: " + m.settings.path.string() + ": cannot rename into place: " + ec.message());
  m.finished = true;
  return true;
}

int VideoExport::frameCount() const { return impl_->total; }
int VideoExport::framesDone() const { return impl_->done; }
float VideoExport::fraction() const {
  return impl_->total > 0 ? static_cast<float>(impl_->done) / static_cast<float>(impl_->total) : 0.0f;
}
const VideoSettings& VideoExport::settings() const { return impl_->settings; }
double VideoExport::seconds() const { return impl_->seconds; }

}  // namespace ew::ui
