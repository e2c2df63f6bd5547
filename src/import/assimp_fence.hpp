// Internal to the assimp importer (import_assimp.cpp): a read by assimp run in a child process
// under limits, so that a bug inside assimp (an endless loop, a segfault, an assertion's
// abort, a huge allocation) becomes one facet::Error instead of a hung or dead caller.
//
// The child is fork()ed without exec: it runs `read` (assimp's read of the file), which writes
// what it found to a memory file the caller reads back (import_assimp.cpp: the scene in
// assimp's own binary dump), and exits.
//
// Forking a multi-threaded process (oneTBB's workers, a Python interpreter) leaves in the child
// only the forking thread; a lock another thread held stays held there. The read must
// therefore touch only what needs no other thread and no lock another thread may hold: assimp's
// importer and exporter (single-threaded, no mutex of their own; the dump's time stamp takes
// glibc's time-zone lock, held only inside localtime and the like), glibc's malloc and stdio
// (which fork() resets in the child), facet's guarded file access. Never oneTBB (its workers are
// gone), never ImportOptions::warn (a Python callback would need the interpreter's lock). Should a
// lock be held all the same, the wall-clock limit turns the stall into an error, not a hang.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "facet/import.hpp"

namespace facet::io {

// What a fenced read handed back: the bytes it wrote, mapped read-only (empty when it wrote
// none, or when the fence is off).
class FencedResult {
 public:
  FencedResult() = default;
  explicit FencedResult(int fd);  // maps the file's bytes; the descriptor stays the caller's
  FencedResult(FencedResult&& other) noexcept;
  FencedResult& operator=(FencedResult&& other) noexcept;
  ~FencedResult();
  std::string_view bytes() const { return {static_cast<const char*>(data_), size_}; }

 private:
  void* data_ = nullptr;
  std::size_t size_ = 0;
};

// Runs `read` in a child process limited by options (import_time_limit_seconds: wall clock,
// enforced here with SIGKILL, and CPU time; import_memory_limit_bytes: RLIMIT_AS, and
// RLIMIT_FSIZE for what it writes; no core file). The read may write its result to the file
// descriptor it is given (an anonymous memory file); returns those bytes when the child exited
// normally, whatever the read found (an error it threw is the caller's to find again). Throws
// facet::Error "<path>: cannot import: ..." when the child crashed, aborted, ran out of its
// memory, was killed or took too long. With options.fence_assimp off, runs nothing and returns
// no bytes.
//
// For tests, the environment variable FACET_FENCE_TEST_FAULT makes the child fail on purpose
// instead of reading: "crash" (SIGSEGV), "abort" (an assertion's message, then abort), "hang"
// (a busy loop), "memory" (allocates twice its limit).
FencedResult run_fenced(const std::string& path, const ImportOptions& options,
                        const std::function<void(int out)>& read);

}  // namespace facet::io
