#pragma once
// The pose detector's converted models for tests (cmake/pose_models.cmake): a test that needs
// them skips with the command that fetches them, or fails under EIGENWALKER_REQUIRE_DATA=1.
#include <cstdlib>
#include <filesystem>

#include "tests/common/test_support.h"
#include "video/pose_model_files.h"

namespace ew::test {

// A cache folder of the test program's own, so tests neither read nor fill the user's.
inline std::filesystem::path useOwnDetectionCache() {
  static const std::filesystem::path folder = makeTempDir("detection_cache");
  setenv("EIGENWALKER_CACHE", folder.c_str(), 1);
  return folder;
}

// The walking video's detections, made once per ctest run. Detecting demo.mp4 takes about
// 45 s, and only one test has to do it afresh: GuiDetect.DetectsTheSports2dWalker… shares its
// cache through the folder ctest names in EW_TEST_SHARED_DETECTIONS (a fixture,
// tests/CMakeLists.txt), and the tests that need the detections but not their making seed
// their own cache from it. Run outside ctest, each test detects for itself.
inline std::filesystem::path sharedDetectionsFolder() {
  const char* env = std::getenv("EW_TEST_SHARED_DETECTIONS");
  return env && *env ? std::filesystem::path(env) : std::filesystem::path();
}

// The cache files under `cacheRoot` (an EIGENWALKER_CACHE folder) into the shared folder.
inline void shareDetectionCache(const std::filesystem::path& cacheRoot) {
  namespace fs = std::filesystem;
  const fs::path shared = sharedDetectionsFolder();
  if (shared.empty()) return;
  fs::remove_all(shared);
  fs::create_directories(shared);
  for (const auto& entry : fs::directory_iterator(cacheRoot / "detections"))
    fs::copy_file(entry.path(), shared / entry.path().filename());
}

// The shared cache files into `cacheRoot`'s; false when there are none to seed it with.
inline bool seedDetectionCache(const std::filesystem::path& cacheRoot) {
  namespace fs = std::filesystem;
  const fs::path shared = sharedDetectionsFolder();
  if (shared.empty() || !fs::is_directory(shared)) return false;
  fs::create_directories(cacheRoot / "detections");
  bool seeded = false;
  for (const auto& entry : fs::directory_iterator(shared)) {
    fs::copy_file(entry.path(), cacheRoot / "detections" / entry.path().filename(),
                  fs::copy_options::overwrite_existing);
    seeded = true;
  }
  return seeded;
}

}  // namespace ew::test

#define EW_REQUIRE_POSE_MODELS()                                                                     \
  do {                                                                                               \
    if (!::ew::findPoseModels()) {                                                                   \
      if (::ew::test::dataRequired()) {                                                              \
        FAIL() << ::ew::missingPoseModelAdvice() << "; EIGENWALKER_REQUIRE_DATA=1";                  \
      } else {                                                                                       \
        GTEST_SKIP() << ::ew::missingPoseModelAdvice();                                              \
      }                                                                                              \
    }                                                                                                \
  } while (0)
