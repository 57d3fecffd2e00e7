#pragma once
// Locating ../shared/data from tests. When the data is absent a test skips with a clear
// message; with EIGENWALKER_REQUIRE_DATA=1 (set by .ci/run) it fails instead.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace ew::test {

// The shared data folder: $EIGENWALKER_DATA if set, else ../shared/data beside the
// source tree. Empty path if it does not exist.
std::filesystem::path sharedDataDir();

// The project's source tree (for committed fixtures in tests/fixtures).
std::filesystem::path sourceDir();

// A fresh, empty temporary directory unique to the calling test. Removed when the test
// passes (one made outside a test: when the program ends with every test passed); kept, and
// its path printed, when it fails, or always with EIGENWALKER_KEEP_TEST_OUTPUT=1.
std::filesystem::path makeTempDir(const std::string& stem);

bool dataRequired();

// A program on $PATH by name (the first executable found), empty when there is none.
std::filesystem::path findProgram(const std::string& name);

// Debian's Chromium for the tests that open a page in a real browser: $EIGENWALKER_CHROMIUM
// if set, else `chromium` (then `chromium-browser`) on $PATH. Empty when there is none.
std::filesystem::path headlessChromium();

// A program run to completion: exit code (-1 when killed), the signal that killed it,
// its peak resident memory, and what it printed (stdout and stderr together).
struct ProgramRun {
  int exitCode = -1;
  int signal = 0;
  long peakRssKb = 0;
  std::string output;
};

// Runs `program` with `arguments` (no shell), output captured through a file in `dir`.
ProgramRun runProgram(const std::string& program, const std::vector<std::string>& arguments,
                      const std::filesystem::path& dir);

// A shell command line run to completion: exit code (-1 when it did not exit) and what it
// wrote to stdout and stderr, each captured through a file in `dir` (removed afterwards).
struct ShellRun {
  int exitCode = -1;
  std::string out, err;
};
ShellRun runShell(const std::string& commandLine, const std::filesystem::path& dir);

#ifdef EW_CLI_PATH
// eigenwalker-cli (this build's: every test program is given its path) with `arguments`, run
// by the shell in `dir`, so relative paths in the arguments are `dir`'s.
inline ShellRun runCli(const std::string& arguments, const std::filesystem::path& dir) {
  return runShell("cd \"" + dir.string() + "\" && \"" + EW_CLI_PATH + "\" " + arguments, dir);
}
#endif

// A whole text file ("" when it cannot be read).
std::string readTextFile(const std::filesystem::path& file);  // byte for byte

// Writes `bytes` as they are (truncating the file).
void writeBinaryFile(const std::filesystem::path& file, const std::string& bytes);

// Same shape and the same doubles bit for bit (a saved file's round trip).
bool bitwiseEqual(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

}  // namespace ew::test

// Use at the top of a test that reads ../shared/data: skips (or fails in CI) when missing.
#define EW_REQUIRE_SHARED_DATA()                                                        \
  do {                                                                                  \
    if (::ew::test::sharedDataDir().empty()) {                                          \
      if (::ew::test::dataRequired()) {                                                 \
        FAIL() << "../shared/data not found and EIGENWALKER_REQUIRE_DATA=1";            \
      } else {                                                                          \
        GTEST_SKIP() << "../shared/data not found beside the checkout (set "            \
                        "EIGENWALKER_DATA to its path to run this test)";               \
      }                                                                                 \
    }                                                                                   \
  } while (0)

// Use at the top of a test that opens a page in headless Chromium: skips when it is not
// installed (fails with EIGENWALKER_REQUIRE_DATA=1, as in CI, where .ci/install-deps.sh
// installs it).
#define EW_REQUIRE_BROWSER()                                                            \
  do {                                                                                  \
    if (::ew::test::headlessChromium().empty()) {                                       \
      if (::ew::test::dataRequired()) {                                                 \
        FAIL() << "chromium not found and EIGENWALKER_REQUIRE_DATA=1 (apt-get install " \
                  "chromium, or set EIGENWALKER_CHROMIUM)";                             \
      } else {                                                                          \
        GTEST_SKIP() << "chromium not found (apt-get install chromium, or set "         \
                        "EIGENWALKER_CHROMIUM to a Chromium to run this test)";         \
      }                                                                                 \
    }                                                                                   \
  } while (0)
