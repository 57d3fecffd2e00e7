#pragma once
// The viewer's message log: what was loaded, warnings from the data, errors. Shown in the
// log panel; errors also in the header. Also echoed to stderr for scripted runs.

#include <chrono>
#include <string>
#include <vector>

namespace ew::ui {

enum class LogLevel { Info, Warning, Error };

struct LogEntry {
  double timeS = 0.0;  // seconds since the log was created
  LogLevel level = LogLevel::Info;
  std::string text;
};

class Log {
 public:
  Log();
  void info(std::string text) { add(LogLevel::Info, std::move(text)); }
  void warning(std::string text) { add(LogLevel::Warning, std::move(text)); }
  void error(std::string text) { add(LogLevel::Error, std::move(text)); }
  void add(LogLevel level, std::string text);
  const std::vector<LogEntry>& entries() const { return entries_; }
  void setEcho(bool echo) { echo_ = echo; }

 private:
  std::chrono::steady_clock::time_point start_;
  std::vector<LogEntry> entries_;
  bool echo_ = false;
};

}  // namespace ew::ui
