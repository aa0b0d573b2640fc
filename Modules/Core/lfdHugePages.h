/**
 * @file   lfdHugePages.h
 * @brief  a light field's passes allocated on transparent huge pages
 *
 * The passes of a light field are tens to hundreds of MB (the demo's fish:
 * 94 MB). Filled on 4 KiB pages, each page costs the kernel a fault, and on
 * a virtual machine a fault is slow: reading the fish (vtkLightFieldReader)
 * took 47 000 faults and 1.05 s of CPU, of which about 0.24 s went to the
 * 22 000 faults of its passes. Where the kernel gives transparent huge pages
 * to the ranges that ask for them (THP in `madvise` mode, the default of most
 * distributions), asking before the first write makes each 2 MiB fault in
 * at once: 25 000 faults and 0.82 s (README, Benchmarks).
 *
 * vtkLightField::AllocatePass() asks for every pass it allocates, before
 * filling it, which covers every reader, importer, synthesizer and filter of
 * lfd. The lookup itself does not read faster from huge pages on the
 * machine measured (the same frame from the same bytes on 4 KiB pages, on
 * huge pages and in numpy's memory took the same CPU time), so memory that
 * came from elsewhere (a DeepCopy, numpy) is not moved onto them.
 */
#ifndef lfdHugePages_h
#define lfdHugePages_h

#include "lfdCoreModule.h" // For export macro

#include <cstddef>

namespace lfd
{
/// The size of a transparent huge page (x86-64, and arm64 with 4 KiB base pages).
constexpr std::size_t HugePageBytes = std::size_t(2) << 20;

/**
 * Asks the kernel to back the whole huge pages within the `bytes` bytes at
 * `data` (the 2 MiB-aligned interior of the range; the pages it shares with
 * other data are left as they are) with transparent huge pages when they are
 * first touched: `madvise(MADV_HUGEPAGE)`. Call it before the range is
 * written: pages already touched stay as they are until the kernel's
 * background collapsing (khugepaged) gets to them. The bytes keep their
 * values.
 *
 * A hint, never an error: a kernel without transparent huge pages or with
 * them set to `never`, a process that disabled them (prctl
 * PR_SET_THP_DISABLE), memory that cannot have them or no free huge page
 * leave the range on base pages. Not Linux: nothing is asked.
 *
 * Returns the bytes of the interior that were advised: 0 when the range
 * holds no whole huge page or nothing was asked.
 */
LFDCORE_EXPORT std::size_t AdviseHugePages(void* data, std::size_t bytes);
}

#endif
