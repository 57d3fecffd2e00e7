#pragma once
// One line of text that must fit a width: cut at a character boundary with "…" appended,
// so that it never runs into what is drawn beside it.

#include <imgui.h>

#include <cstddef>
#include <string>
#include <vector>

namespace ew::ui {

// `text` (one line), shortened to at most `maxWidth` pixels in the current font.
inline std::string fitText(const std::string& text, float maxWidth) {
  if (ImGui::CalcTextSize(text.c_str()).x <= maxWidth) return text;
  const char* ellipsis = "…";
  const float room = maxWidth - ImGui::CalcTextSize(ellipsis).x;
  if (room <= 0.0f) return "";
  // UTF-8 character starts; the longest prefix that fits, by bisection.
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < text.size(); ++i)
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) starts.push_back(i);
  std::size_t lo = 0, hi = starts.size();  // prefix of starts[lo] bytes fits (lo = 0: empty)
  while (lo + 1 < hi) {
    const std::size_t mid = (lo + hi) / 2;
    const std::string prefix = text.substr(0, starts[mid]);
    if (ImGui::CalcTextSize(prefix.c_str()).x <= room) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  std::string out = text.substr(0, starts.empty() ? 0 : starts[lo]);
  while (!out.empty() && (out.back() == ' ' || out.back() == ',' || out.back() == ':'))
    out.pop_back();
  return out + ellipsis;
}

}  // namespace ew::ui
