#pragma once
/// \file Allocator.hpp
/// Process-wide memory allocator settings of the driver.

namespace signorini::core {

/// With glibc: blocks up to 32 MiB come from the heap, and freed memory is kept for reuse rather
/// than returned to the system. An adaptive run builds and frees the matrices, vectors and
/// assembly lists of a new mesh in every time step; with glibc's defaults each such block was
/// mapped, cleared page by page by the kernel and unmapped again (docs/adaptive-step-cost-history.md,
/// twentieth entry). The peak resident memory of the paper deck stayed at 107 MB; freed memory is
/// no longer returned to the system before the process ends, and heap fragmentation could raise the
/// peak of other runs. Call once, first thing in main(); a no-op on other C libraries, or when the
/// environment sets MALLOC_MMAP_THRESHOLD_, MALLOC_TRIM_THRESHOLD_ or GLIBC_TUNABLES (the user's
/// own choice wins).
void keepFreedMemory();

}  // namespace signorini::core
