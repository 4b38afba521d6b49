// The tool's sub-commands. Each returns the process exit code and throws UsageError for bad
// arguments or input.
#ifndef deepshadow_tool_Commands_h
#define deepshadow_tool_Commands_h

#include "Options.h"

namespace deepshadow
{
namespace tool
{

int RunRender(const Options& options);
int RunReference(const Options& options);
int RunAll(const Options& options);
int RunScenes(const Options& options);
int RunPresets(const Options& options);
int RunGallery(const Options& options);
int RunBench(const Options& options);
int RunShadowBench(const Options& options);
int RunReport(const Options& options);

}
}
#endif
