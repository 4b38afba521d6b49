// The tool's memory budget: what a command will ask for, estimated from its options before
// anything large is allocated, and refused with one line naming the bytes (not
// std::bad_alloc, or the kernel killing the process; --size 16384x16384 asked OSMesa for
// about 15 GB). The figures per pixel and texel were measured on llvmpipe (Documentation/HostileInput.md,
// "the tool's memory budget"); they are estimates, so the budget leaves room: by default half the machine's
// memory (deepshadow::DefaultMemoryBudget), or --memory-budget.
#ifndef deepshadow_tool_Budget_h
#define deepshadow_tool_Budget_h

#include "Options.h"

#include <cstdint>

class vtkImageData;

namespace deepshadow
{
namespace tool
{

/** --memory-budget, or the machine's default. */
std::uint64_t MemoryBudget(const Options& options);

/** Bytes of the frame: window, VTK's buffers, peeled layers and segments, the captures. */
std::uint64_t FrameBytes(const Options& options, int width, int height, bool pass);

/** Bytes of the shadow structures of one volume's technique, over the options' lights. */
std::uint64_t ShadowBytes(const Options& options);

/** Bytes the mapper adds for a volume: its float copy and 3D texture. */
std::uint64_t VolumeBytes(vtkImageData* data);

/**
 * Throws UsageError if the frame, the shadow structures, the volume or their sum exceed the
 * budget; `pass` says whether meshes or a second volume bring vtkDeepShadowPass's buffers,
 * `volumes` how many volumes carry a technique.
 */
void RequireWithinBudget(const Options& options, vtkImageData* data, bool pass, int volumes);

}
}
#endif
