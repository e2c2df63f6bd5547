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

}  // namespace facet::cli
