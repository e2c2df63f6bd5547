// For tests that need a Debian package's files (assimp-testmodels, glmark2-data, xvfb): on a
// developer's machine without the package they are skipped with a note; in CI (the CI variable
// set, as .ci/run runs) they fail, because `make test` installs every package they need.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>

// Returns from the calling function (a test, or a void helper of one) unless `present`.
#define FACET_REQUIRE_PACKAGE(present, message)                          \
  do {                                                                   \
    if (!(present)) {                                                    \
      if (std::getenv("CI") != nullptr) FAIL() << message << " (in CI)"; \
      GTEST_SKIP() << message;                                           \
    }                                                                    \
  } while (false)
