#pragma once
// Widgets for panels that must hold at any width (issue 18: a small window or a large UI
// scale cuts no label at the panel's edge). Toggles go on the same line while they fit and
// wrap onto the next otherwise; a label too long for the panel wraps between words.

#include <initializer_list>
#include <utility>

namespace ew::ui {

// The width of a radio button or checkbox with its label, and of a button.
float toggleWidth(const char* label);
float buttonWidth(const char* label);
// Before an item `width` wide that would follow the previous one: the same line when it fits,
// else the next. `spacing` < 0: the style's item spacing.
void sameLineOrWrap(float width, float spacing = -1.0f);
// A checkbox or radio button whose label, when the panel is too narrow for it on one line,
// wraps between words beside the box (clicking the label still toggles).
bool checkboxWrapped(const char* label, bool* value);
bool radioWrapped(const char* label, bool active);
// Radio buttons of `count` labels choosing *value, laid out on as many lines as the panel needs.
bool radioRow(const char* const* labels, int count, int* value);
// Greyed text that wraps between words at the panel's edge.
void textDisabledWrapped(const char* text);
// Equal buttons (label, enabled) filling the width, on as many rows as their labels need;
// returns the index clicked (-1: none).
int buttonRow(std::initializer_list<std::pair<const char*, bool>> buttons);

}  // namespace ew::ui
