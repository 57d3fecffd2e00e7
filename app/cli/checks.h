#pragma once
// Number checks for the command line's options. CLI11's PositiveNumber and NonNegativeNumber
// let NaN through (every comparison with it is false) and word a refused infinity as "not in
// range 0.000000 to 179769313486231570814527…" (three hundred digits); these refuse both,
// saying what a value must be.
#include <CLI/CLI.hpp>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>

namespace ew::cli {

namespace detail {

// `help`: what --help shows after the option's type ("POSITIVE", "in [0.5 - 2.5]").
inline CLI::Validator numberCheck(const std::string& help, const std::string& must, std::function<bool(double)> ok) {
  return CLI::Validator(
      [must, ok](std::string& text) -> std::string {
        double x = 0.0;
        if (!CLI::detail::lexical_cast(text, x) || !ok(x)) return "Value " + text + " is not " + must;
        return "";
      },
      help);
}

}  // namespace detail

// A number above zero, finite (a focal length, a frame rate, σ²).
inline const CLI::Validator kPositiveFinite =
    detail::numberCheck("POSITIVE", "a positive finite number", [](double x) { return std::isfinite(x) && x > 0.0; });
// A finite number from `low` to `high`, both included (CLI::Range lets NaN through).
inline CLI::Validator finiteIn(double low, double high) {
  std::ostringstream from, in;
  from << low << " to " << high;
  in << "in [" << low << " - " << high << "]";
  return detail::numberCheck(in.str(), "a number from " + from.str(),
                             [low, high](double x) { return std::isfinite(x) && x >= low && x <= high; });
}
// Zero or above, finite (a frame number, a noise level).
inline const CLI::Validator kNonNegativeFinite = detail::numberCheck(
    "NONNEGATIVE", "a finite number of zero or more", [](double x) { return std::isfinite(x) && x >= 0.0; });
// Any finite number (an angle in degrees).
inline const CLI::Validator kFinite =
    detail::numberCheck("FINITE", "a finite number", [](double x) { return std::isfinite(x); });

}  // namespace ew::cli
