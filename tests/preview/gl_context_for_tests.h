// One headless OpenGL 4.5 context for a test binary (preview/gl_context.h). Tests may skip
// only where no such context can be made at all, and never in CI (the CI variable is set).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "preview/gl_context.h"

namespace phellem::test {

inline preview::HeadlessGl* shared_gl(std::string* why) {
  static std::string reason;
  static std::unique_ptr<preview::HeadlessGl> gl = preview::HeadlessGl::create(&reason);
  *why = reason;
  return gl.get();
}

}  // namespace phellem::test

// At the start of a GL test: a current context, or a skip (a failure in CI).
#define PHELLEM_REQUIRE_GL()                                                                   \
  do {                                                                                         \
    std::string why_;                                                                          \
    if (!phellem::test::shared_gl(&why_)) {                                                    \
      if (std::getenv("CI")) FAIL() << "no OpenGL 4.5 context in CI: " << why_;               \
      GTEST_SKIP() << "no OpenGL 4.5 context: " << why_;                                       \
    }                                                                                          \
  } while (0)
