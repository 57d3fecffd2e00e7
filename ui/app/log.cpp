#include "ui/app/log.h"

#include <cstdio>

namespace ew::ui {

Log::Log() : start_(std::chrono::steady_clock::now()) {}

void Log::add(LogLevel level, std::string text) {
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (echo_ || level == LogLevel::Error) {
    const char* tag = level == LogLevel::Error ? "error" : level == LogLevel::Warning ? "warning" : "info";
    std::fprintf(stderr, "eigenwalker: %s: %s\n", tag, text.c_str());
  }
  entries_.push_back({t, level, std::move(text)});
  if (entries_.size() > 2000) entries_.erase(entries_.begin(), entries_.begin() + 500);
}

}  // namespace ew::ui
