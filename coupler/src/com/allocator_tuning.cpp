#include "com/allocator_tuning.hpp"

#include <malloc.h>

namespace cosim::com {

void tune_allocator_for_large_fields() {
  static const bool done = [] {
    constexpr int one_gib = 1 << 30;
    mallopt(M_ARENA_MAX, 1);
    mallopt(M_MMAP_THRESHOLD, one_gib);
    mallopt(M_TRIM_THRESHOLD, one_gib);
    return true;
  }();
  (void)done;
}

}  // namespace cosim::com
