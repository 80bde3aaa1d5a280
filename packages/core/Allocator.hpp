#pragma once
/// \file Allocator.hpp
/// Process-wide memory allocator settings of the driver.

namespace signorini::core {

/// With glibc: blocks up to 32 MiB come from the heap, and freed memory is kept for reuse rather
/// than returned to the system. An adaptive run builds and frees the matrices, vectors and
/// assembly lists of a new mesh in every time step; with glibc's defaults each such block was
/// mapped, cleared page by page by the kernel and unmapped again (docs/adaptive-step-cost-history.md,
/// twentieth entry). The peak memory is unchanged. Call once, first thing in main(); a no-op on
/// other C libraries, or when the environment sets MALLOC_MMAP_THRESHOLD_ or MALLOC_TRIM_THRESHOLD_
/// (the user's own choice wins).
void keepFreedMemory();

}  // namespace signorini::core
