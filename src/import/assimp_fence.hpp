// Internal to the assimp importer (import_assimp.cpp): a read by assimp run first in a child
// process under limits, so that a bug inside assimp (an endless loop, a segfault, an assertion's
// abort, a huge allocation) becomes one facet::Error instead of a hung or dead caller.
//
// The child is fork()ed without exec and only probes: it runs `probe` (assimp's read of the
// file) and exits; the caller then reads the file for real, knowing the same read ends. That
// costs a second read by assimp, but nothing has to come back from the child, so no serializer
// has to follow the Scene's fields (docs/import.md has the measured cost).
//
// Forking a multi-threaded process (oneTBB's workers, a Python interpreter) leaves in the child
// only the forking thread; a lock another thread held stays held there. The probe must
// therefore touch only what needs no other thread and no lock another thread may hold: assimp's
// importer (single-threaded, no mutex of its own), glibc's malloc and stdio (which fork() resets
// in the child), facet's guarded file access. Never oneTBB (its workers are gone), never
// ImportOptions::warn (a Python callback would need the interpreter's lock). Should a lock be
// held all the same, the wall-clock limit turns the stall into an error, not a hang.
#pragma once

#include <functional>
#include <string>

#include "facet/import.hpp"

namespace facet::io {

// Runs `probe` in a child process limited by options (import_time_limit_seconds: wall clock,
// enforced here with SIGKILL, and CPU time; import_memory_limit_bytes: RLIMIT_AS; no core
// file). Returns when the child exited normally, whatever the probe found (an error it threw
// is the real read's to report). Throws facet::Error "<path>: cannot import: ..." when the child
// crashed, aborted, ran out of its memory, was killed or took too long.
//
// For tests, the environment variable FACET_FENCE_TEST_FAULT makes the child fail on purpose
// instead of probing: "crash" (SIGSEGV), "abort" (an assertion's message, then abort), "hang"
// (a busy loop), "memory" (allocates twice its limit).
void run_fenced(const std::string& path, const ImportOptions& options,
                const std::function<void()>& probe);

}  // namespace facet::io
