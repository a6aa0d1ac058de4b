#pragma once

namespace cosim::com {

// Makes glibc reuse memory for large field buffers instead of mapping fresh
// pages for every message: one malloc arena (ZeroMQ's I/O thread would
// otherwise get its own, which maps every chunk above 64 MB anew), no mmap
// below 1 GiB and no trimming. Fresh pages cost a page fault each on first
// touch (~10 µs on the project's VMs: 80 MB fields went at 0.2 GB/s instead
// of 5 GB/s). Called once by every coupled process before its transport
// starts; idempotent.
void tune_allocator_for_large_fields();

}  // namespace cosim::com
