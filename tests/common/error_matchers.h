#pragma once
// Assertions on the project's typed errors (core/common/errors.h).

#include <gtest/gtest.h>

#include <exception>
#include <initializer_list>
#include <string>
#include <string_view>

#include "core/common/errors.h"

namespace ew::test {

// Passes when f throws ew::Error of `kind` whose message contains every part.
template <class F>
::testing::AssertionResult throwsError(F&& f, ErrorKind kind,
                                       std::initializer_list<std::string_view> parts) {
  try {
    f();
  } catch (const Error& e) {
    const std::string message = e.what();
    if (e.kind() != kind) {
      return ::testing::AssertionFailure() << "kind " << errorKindName(e.kind()) << ", expected "
                                           << errorKindName(kind) << ": " << message;
    }
    for (const auto part : parts) {
      if (message.find(part) == std::string::npos)
        return ::testing::AssertionFailure() << "message lacks '" << part << "': " << message;
    }
    return ::testing::AssertionSuccess() << message;
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "not an ew::Error: " << e.what();
  }
  return ::testing::AssertionFailure() << "no exception";
}

}  // namespace ew::test
