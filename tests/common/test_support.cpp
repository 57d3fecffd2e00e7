#include "tests/common/test_support.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <vector>

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

namespace {

// EIGENWALKER_KEEP_GUI_OUTPUT is the viewer tests' older name for the same wish.
bool keepTestOutput() {
  for (const char* name : {"EIGENWALKER_KEEP_TEST_OUTPUT", "EIGENWALKER_KEEP_GUI_OUTPUT"})
    if (const char* keep = std::getenv(name); keep && *keep == '1') return true;
  return false;
}

// The temporary directories made during the running test, and outside any test.
std::vector<std::filesystem::path>& testDirs() {
  static std::vector<std::filesystem::path> dirs;
  return dirs;
}
std::vector<std::filesystem::path>& programDirs() {
  static std::vector<std::filesystem::path> dirs;
  return dirs;
}

void removeOrReport(std::vector<std::filesystem::path>& dirs, bool passed) {
  for (const auto& dir : dirs) {
    std::error_code ignored;
    if (passed && !keepTestOutput())
      std::filesystem::remove_all(dir, ignored);
    else if (std::filesystem::exists(dir, ignored))
      std::cout << "test output kept in " << dir.string() << "\n";
  }
  dirs.clear();
}

// A test's directories go with it when it passes (a `make test` left about a hundred behind
// in the temporary directory each run, 6 GB over a month of runs).
class TempDirCleaner : public ::testing::EmptyTestEventListener {
  void OnTestEnd(const ::testing::TestInfo& info) override { removeOrReport(testDirs(), info.result()->Passed()); }
  void OnTestProgramEnd(const ::testing::UnitTest& unit) override { removeOrReport(programDirs(), unit.Passed()); }
};

const bool kCleanerInstalled = [] {
  ::testing::UnitTest::GetInstance()->listeners().Append(new TempDirCleaner);
  return true;
}();

}  // namespace

std::filesystem::path makeTempDir(const std::string& stem) {
  (void)kCleanerInstalled;
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
  (info ? testDirs() : programDirs()).push_back(dir);
  return dir;
}

bool dataRequired() {
  const char* env = std::getenv("EIGENWALKER_REQUIRE_DATA");
  return env && std::string(env) == "1";
}

std::filesystem::path findProgram(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (folder.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(folder) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

std::filesystem::path headlessChromium() {
  if (const char* env = std::getenv("EIGENWALKER_CHROMIUM"); env && *env)
    return access(env, X_OK) == 0 ? std::filesystem::path(env) : std::filesystem::path();
  for (const char* name : {"chromium", "chromium-browser"})
    if (auto found = findProgram(name); !found.empty()) return found;
  return {};
}

ProgramRun runProgram(const std::string& program, const std::vector<std::string>& arguments,
                      const std::filesystem::path& dir) {
  const std::string log = (dir / "program_output.txt").string();
  std::vector<std::string> words = {program};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  ProgramRun run;
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) _exit(126);
    dup2(fd, 1);
    dup2(fd, 2);
    execv(program.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (pid < 0 || wait4(pid, &status, 0, &usage) != pid) return run;
  if (WIFEXITED(status)) run.exitCode = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
  run.peakRssKb = usage.ru_maxrss;
  run.output = readTextFile(log);
  return run;
}

std::string readTextFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void writeBinaryFile(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << bytes;
}

bool bitwiseEqual(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0;
}

ShellRun runShell(const std::string& commandLine, const std::filesystem::path& dir) {
  const auto out = dir / "shell_stdout.txt", err = dir / "shell_stderr.txt";
  const std::string command =
      commandLine + " > \"" + out.string() + "\" 2> \"" + err.string() + "\"";
  const int status = std::system(command.c_str());
  ShellRun r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, readTextFile(out), readTextFile(err)};
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace ew::test
