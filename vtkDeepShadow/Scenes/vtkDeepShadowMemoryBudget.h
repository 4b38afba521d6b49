/**
 * Memory budgets: how many bytes one input, frame or shadow structure may ask for before it
 * is refused with a clear error naming the bytes (instead of std::bad_alloc, or the kernel
 * killing the process). Used by the file readers and the deepshadow tool.
 */
#ifndef vtkDeepShadowMemoryBudget_h
#define vtkDeepShadowMemoryBudget_h

#include "vtkDeepShadowScenesModule.h" // For export macro

#include <cstdint> // For std::uint64_t
#include <string>  // For std::string

namespace deepshadow
{

/**
 * Half the physical memory, or half the address-space limit (`ulimit -v`) when that is
 * lower: the rest is left for the libraries, the GL driver's copies and the system.
 */
VTKDEEPSHADOWSCENES_EXPORT std::uint64_t DefaultMemoryBudget();

/** `count` times `size`, saturating at UINT64_MAX instead of wrapping. */
VTKDEEPSHADOWSCENES_EXPORT std::uint64_t SaturatingProduct(std::uint64_t count, std::uint64_t size);

/**
 * "" when `bytes` fit in `budget`, else one line: "WHAT would take N bytes (1.2 GiB), more than
 * the memory budget of M bytes (...)".
 */
VTKDEEPSHADOWSCENES_EXPORT std::string CheckMemoryBudget(
  const std::string& what, std::uint64_t bytes, std::uint64_t budget);

}
#endif
