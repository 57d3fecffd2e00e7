#pragma once
// The pose detector's converted models for tests (cmake/pose_models.cmake): a test that needs
// them skips with the command that fetches them, or fails under EIGENWALKER_REQUIRE_DATA=1.
#include <cstdlib>
#include <filesystem>

#include "tests/common/test_support.h"
#include "video/pose_model_files.h"

namespace ew::test {

// A cache folder of the test program's own, so tests neither read nor fill the user's.
inline void useOwnDetectionCache() {
  static const std::filesystem::path folder = makeTempDir("detection_cache");
  setenv("EIGENWALKER_CACHE", folder.c_str(), 1);
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
