#include "tests/common/test_support.h"

#include <cstdlib>
#include <random>

namespace ew::test {

std::filesystem::path sharedDataDir() {
  std::filesystem::path dir;
  if (const char* env = std::getenv("EIGENWALKER_DATA"); env && *env) {
    dir = env;
  } else {
    dir = EW_SHARED_DATA_DIR;
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return {};
  return std::filesystem::weakly_canonical(dir, ec);
}

std::filesystem::path sourceDir() { return EW_SOURCE_DIR; }

std::filesystem::path makeTempDir(const std::string& stem) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = stem;
  if (info) name += std::string("_") + info->test_suite_name() + "_" + info->name();
  for (char& c : name) {
    if (c == '/' || c == ' ') c = '_';
  }
  std::random_device rd;
  auto dir = std::filesystem::temp_directory_path() /
             ("ew_" + name + "_" + std::to_string(rd() % 1000000));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

bool dataRequired() {
  const char* env = std::getenv("EIGENWALKER_REQUIRE_DATA");
  return env && std::string(env) == "1";
}

}  // namespace ew::test
