#include "lfdHugePages.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h> // madvise
#endif

namespace lfd
{
//------------------------------------------------------------------------------
std::size_t AdviseHugePages(void* data, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(data);
  if (!data || bytes < HugePageBytes || begin > UINTPTR_MAX - bytes)
  {
    return 0;
  }
  const std::uintptr_t first = (begin + HugePageBytes - 1) & ~(HugePageBytes - 1);
  const std::uintptr_t last = (begin + bytes) & ~(HugePageBytes - 1);
  if (first >= last)
  {
    return 0;
  }
  // A hint: a failure (EINVAL without THP, ENOMEM...) leaves the pages as
  // they would have been.
  madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  return last - first;
#else
  static_cast<void>(data);
  static_cast<void>(bytes);
  return 0;
#endif
}
}
