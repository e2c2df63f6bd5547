// How the program asks for memory: tuned for a short run that loads, renders, writes and exits.
#pragma once

namespace facet::cli {

// Called first thing in main(). A thumbnail run spends much of its kernel time in page faults:
// the importer, the frame's buffers and the vertex arrays touch tens of megabytes of fresh 4 KiB
// pages, one fault each, and glibc hands big blocks back to the kernel when they are freed, to
// fault them in again at the next allocation. So blocks come from the heap and stay there, and
// the heap's first kHeapReserve bytes are backed by 2 MiB pages where the kernel offers
// transparent huge pages on request (Debian's 'madvise' mode): one fault then maps 512 pages.
// Every step is a hint; where one is refused (another allocator, as under a sanitizer), memory
// behaves as before.
void use_memory_for_short_run();

// Called once a model is loaded. The importer's working arrays (a big STL's corner list and weld
// table: more than the mesh it makes) are free by then but stay in the heap, resident, where the
// frame reuses only what fits its blocks; past kReleaseAbove bytes free, their pages go back to
// the kernel, so that the peak is what the mesh and the frame touch. Smaller models keep theirs
// for the frame, as use_memory_for_short_run intends.
void release_import_leftovers();

}  // namespace facet::cli
