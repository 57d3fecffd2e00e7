// The replay runner: a main() for the harnesses of tests/fuzz/ in builds without libFuzzer
// (GCC, `make test`, `make test-sanitize`). Runs every file given, and every file under
// every folder given (recursively, in name order), once through LLVMFuzzerTestOneInput:
//
//   fuzz_c3d tests/fuzz/regressions/c3d build/fuzz/seeds/c3d
//
// Exit 0 when every input was handled (parsed, or rejected with an ew::Error); 1 when an
// input threw anything else (named, with what it threw), or a path does not exist. A crash
// or a sanitizer report ends the process, so each input is named before it runs.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/fuzz/fuzz_common.h"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputsUnder(const fs::path& path) {
  std::vector<fs::path> files;
  if (fs::is_directory(path)) {
    for (const auto& entry : fs::recursive_directory_iterator(path)) {
      if (entry.is_regular_file()) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
  } else {
    files.push_back(path);
  }
  return files;
}

std::vector<std::uint8_t> readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string self = fs::path(argv[0]).filename().string();
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE_OR_FOLDER...\n", self.c_str());
    return 2;
  }
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i) {
    if (!fs::exists(argv[i])) {
      std::fprintf(stderr, "%s: %s does not exist\n", self.c_str(), argv[i]);
      return 1;
    }
    const auto files = inputsUnder(argv[i]);
    inputs.insert(inputs.end(), files.begin(), files.end());
  }
  int findings = 0;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const auto bytes = readBytes(inputs[k]);
    std::fprintf(stderr, "%s: [%zu/%zu] %s (%zu bytes)", self.c_str(), k + 1, inputs.size(),
                 inputs[k].string().c_str(), bytes.size());
    std::fflush(stderr);
    const auto start = std::chrono::steady_clock::now();
    try {
      LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "\n  FINDING: threw %s, not ew::Error\n", e.what());
      ++findings;
      continue;
    } catch (...) {
      std::fprintf(stderr, "\n  FINDING: threw a non-std exception\n");
      ++findings;
      continue;
    }
    const std::chrono::duration<double, std::milli> ms = std::chrono::steady_clock::now() - start;
    std::fprintf(stderr, " %.0f ms\n", ms.count());
  }
  std::printf("%s: %zu inputs replayed, %d findings\n", self.c_str(), inputs.size(), findings);
  return findings == 0 ? 0 : 1;
}
