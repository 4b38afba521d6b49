// A minimal parallel loop for the CPU reference: deterministic results (each index is
// computed by exactly one thread, writing only its own output), dynamic load balancing.
#ifndef deepshadow_Parallel_h
#define deepshadow_Parallel_h

#include "vtkDeepShadowCoreModule.h"

#include <functional>

namespace deepshadow
{

/** Threads used when 0 is asked for: DEEPSHADOW_THREADS, else the hardware's count. */
VTKDEEPSHADOWCORE_EXPORT int DefaultThreadCount();

/** Calls body(i) for i in [0, count) on `threads` threads (0: DefaultThreadCount()). */
VTKDEEPSHADOWCORE_EXPORT void ParallelFor(
  int count, const std::function<void(int)>& body, int threads = 0);

}
#endif
