// lfd::AdviseHugePages: advises exactly the 2 MiB-aligned interior of a
// range, nothing for a range without a whole huge page, and never changes
// the bytes (a hint, whatever the kernel's THP setting).
#include "lfdHugePages.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace
{
int Check(bool ok, const char* what)
{
  if (!ok)
  {
    std::fprintf(stderr, "FAILED: %s\n", what);
  }
  return ok ? 0 : 1;
}
}

int TestHugePages(int, char*[])
{
  int failures = 0;
  const std::size_t huge = lfd::HugePageBytes;
  failures += Check(lfd::AdviseHugePages(nullptr, 4 * huge) == 0, "nullptr advises nothing");

  // 3 huge pages and a bit, starting 1 byte past a huge-page boundary: the
  // interior is the 2 whole huge pages after the first boundary.
  std::vector<std::uint8_t> buffer(5 * huge);
  const std::uintptr_t base = reinterpret_cast<std::uintptr_t>(buffer.data());
  std::uint8_t* aligned = buffer.data() + ((huge - base % huge) % huge);
  for (std::size_t i = 0; i < buffer.size(); ++i)
  {
    buffer[i] = static_cast<std::uint8_t>(i * 7 + 3);
  }
  const std::vector<std::uint8_t> before = buffer;

  failures += Check(lfd::AdviseHugePages(aligned + 1, huge) == 0,
    "a range of one huge page that straddles a boundary holds no whole page");
  failures +=
    Check(lfd::AdviseHugePages(aligned + 1, huge - 1) == 0, "a range smaller than a huge page");
  failures += Check(lfd::AdviseHugePages(aligned, 0) == 0, "an empty range");
  const std::size_t advised = lfd::AdviseHugePages(aligned + 1, 3 * huge + 5);
#if defined(__linux__)
  failures += Check(advised == 2 * huge, "the interior of 3 huge pages and a bit is 2 pages");
  failures += Check(lfd::AdviseHugePages(aligned, 2 * huge) == 2 * huge, "an aligned range");
#else
  failures += Check(advised == 0, "no advice off Linux");
#endif
  failures += Check(buffer == before, "the bytes keep their values");
  std::printf("advised %zu bytes of a range of %zu\n", advised, 3 * huge + 5);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
