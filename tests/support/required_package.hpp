// For tests that need a Debian package's files (assimp-testmodels, glmark2-data, xvfb): `make
// test` installs every package they need (the Makefile's PACKAGES), so a missing one means a
// broken set-up, and the test fails saying which package to install rather than passing.
#pragma once

#include <gtest/gtest.h>

// Fails the calling function (a test, or a void helper of one) unless `present`.
#define FACET_REQUIRE_PACKAGE(present, message)                        \
  do {                                                                 \
    if (!(present)) FAIL() << message << " (`make deps` installs it)"; \
  } while (false)
