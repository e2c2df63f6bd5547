# FACET_SANITIZE: build every target of this project (library, program, tests) with a sanitizer.
#   address -> AddressSanitizer + UndefinedBehaviorSanitizer, any error is fatal
#   thread  -> ThreadSanitizer (defines FACET_SANITIZE_THREAD, see cmake/tsan.supp for why)
# Directory-wide flags, so they reach every target defined after this file is included, for
# compiling and for linking, and never leak into the installed package's usage requirements.
# Use with CMAKE_BUILD_TYPE=RelWithDebInfo; make test-sanitize sets its flags to -O1 -g1 (line info
# for stack traces, and a faster build than -O2 -g).

# The program's and the tests' own files, which drive the library rather than do its work, compile
# at -O0 in sanitizer builds (FACET_SANITIZE_DRIVER_OPTIONS, used by those targets): instrumented
# at -O1 they compile far slower, and the suite's time is spent in the library, which keeps the
# build type's -O1.
set(FACET_SANITIZE_DRIVER_OPTIONS "")
set(FACET_SANITIZE_FLAGS_TEXT "")
if(FACET_SANITIZE STREQUAL "")
  return()
elseif(FACET_SANITIZE STREQUAL "address")
  # UBSan's null and alignment checks are left out: together they guard nearly every pointer
  # use and cost a quarter to a third of the build's compile time. A null dereference still
  # stops the run (ASan reports the SEGV with its stack), and facet reads file data with memcpy,
  # never through a cast pointer that could be misaligned.
  set(_facet_sanitize_flags
    -fsanitize=address,undefined -fno-sanitize=null,alignment -fno-omit-frame-pointer
    -fno-sanitize-recover=all)
elseif(FACET_SANITIZE STREQUAL "thread")
  set(_facet_sanitize_flags -fsanitize=thread -fno-omit-frame-pointer)
  # oneTBB's scheduler lives in an uninstrumented libtbb.so, so TSan cannot see the
  # happens-before edges of its task hand-off and reports races that are not there. Code that
  # runs work in parallel checks FACET_SANITIZE_THREAD and uses plain std::thread workers
  # instead, which TSan understands completely. See cmake/tsan.supp.
  add_compile_definitions(FACET_SANITIZE_THREAD=1)
else()
  message(FATAL_ERROR
    "FACET_SANITIZE must be empty, 'address' or 'thread' (got '${FACET_SANITIZE}')")
endif()

# Sanitizer builds compile the SIMD kernels for AVX2 and the portable fallback only, not also
# for SSSE3, SSE4 and the AVX-512 targets: what they check (memory, threads) is the same on
# every target, every target's results are checked against the others in the Release build's
# tests, and the multi-target kernels are most of the library's compile time, which CI's 20
# minutes need. (HWY_DISABLED_TARGETS: HWY_SSSE3 | HWY_SSE4 | HWY_AVX3 | HWY_AVX3_DL.)
add_compile_definitions(HWY_DISABLED_TARGETS=6528)

set(FACET_SANITIZE_DRIVER_OPTIONS -O0)
add_compile_options(${_facet_sanitize_flags})
add_link_options(${_facet_sanitize_flags})
# The install test builds its example programs with the same flags (they link sanitized libraries).
list(JOIN _facet_sanitize_flags " " FACET_SANITIZE_FLAGS_TEXT)
message(STATUS "facet: sanitizer '${FACET_SANITIZE}': ${FACET_SANITIZE_FLAGS_TEXT}")
