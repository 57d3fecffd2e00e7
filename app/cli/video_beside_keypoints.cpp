#include "app/cli/video_beside_keypoints.h"

#include <iostream>

#ifdef EW_HAVE_VIDEO
#include "video/video_beside.h"
#endif

namespace ew::cli {

void takeTheVideoBeside(const std::filesystem::path& keypoints, KeypointOptions& k) {
#ifdef EW_HAVE_VIDEO
  if (auto beside = videoBesideKeypoints(keypoints)) {
    std::cerr << "the video beside " << keypoints.string() << ": " << beside->file << " (" << beside->size.width
              << "x" << beside->size.height << ", " << beside->fps << " fps)\n";
    k.video = std::move(beside);
  }
#else
  (void)keypoints, (void)k;
#endif
}

}  // namespace ew::cli
