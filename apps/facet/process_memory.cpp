#include "process_memory.hpp"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

namespace facet::cli {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr int kHeapReserve = 256 << 20;
constexpr std::size_t kReleaseAbove = std::size_t{256} << 20;

}  // namespace

void use_memory_for_short_run() {
  // Blocks of up to 1 GiB from the heap rather than each its own mapping, and the heap never
  // trimmed: the process exits soon and gives everything back at once.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, -1);
  // The next time the heap grows, by kHeapReserve more than it needs: reserved, not touched.
  mallopt(M_TOP_PAD, kHeapReserve);
  void* block = std::malloc(1 << 20);  // larger than what the heap has free: it grows now
  if (block == nullptr) return;
  const auto begin = (reinterpret_cast<std::uintptr_t>(block) + kHugePage - 1) & ~(kHugePage - 1);
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  std::free(block);
  mallopt(M_TOP_PAD, 128 << 10);  // glibc's default again for later growth
}

void release_import_leftovers() {
  if (mallinfo2().fordblks >= kReleaseAbove) malloc_trim(0);
}

}  // namespace facet::cli
