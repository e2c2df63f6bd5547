// The frame's big arrays' blocks (frame.hpp's UninitializedAllocator): their own mappings from
// kMappedBlockBytes on, the C++ heap below.
#include <sys/mman.h>

#include <cstddef>
#include <new>

#include "pipeline/frame.hpp"

namespace facet::pipeline {

void* allocate_block(std::size_t bytes) {
  if (bytes < kMappedBlockBytes) return ::operator new(bytes);
  void* block = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (block == MAP_FAILED) throw std::bad_alloc();
  return block;
}

void free_block(void* block, std::size_t bytes) {
  if (bytes < kMappedBlockBytes) {
    ::operator delete(block);
    return;
  }
  munmap(block, bytes);
}

}  // namespace facet::pipeline
