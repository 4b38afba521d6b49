// The tool's sub-commands. Each returns the process exit code and throws UsageError for bad
// arguments or input.
#ifndef deepshadow_tool_Commands_h
#define deepshadow_tool_Commands_h

#include "Options.h"

#include <functional>

namespace deepshadow
{
namespace tool
{

int RunRender(const Options& options);
int RunReference(const Options& options);
int RunAll(const Options& options);
int RunScenes(const Options& options);
int RunPresets(const Options& options);
int RunSeries(const Options& options);
int RunGallery(const Options& options);
int RunView(const Options& options);
/** view's own options (--keys, --screenshots); false if `key` is not one. */
bool ParseViewerOption(Options& o, const std::string& key, const std::function<std::string()>& next);
int RunBench(const Options& options);
int RunShadowBench(const Options& options);
int RunReport(const Options& options);

}
}
#endif
