// deepshadow: the command-line tool of vtkDeepShadow. See `deepshadow --help`.
#include "Commands.h"
#include "Messages.h"
#include "Options.h"
#include "Outputs.h"

#include "vtkVersionMacros.h"

#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>
#include <new>

namespace
{
int Run(const deepshadow::tool::Options& options)
{
  using namespace deepshadow::tool;
  if (options.Command == "help")
  {
    std::cout << (options.HelpCommand.empty() ? Options::Usage()
                                              : Options::CommandUsage(options.HelpCommand));
    return 0;
  }
  if (options.Command == "version")
  {
    std::cout << "deepshadow " << DEEPSHADOW_VERSION << " (vtkDeepShadow, built with VTK "
              << VTK_VERSION << ")\n";
    return 0;
  }
  // Output files that cannot be written, or would replace an input or each other, are said
  // before any work.
  for (const NamedFile& output : options.OutputFiles())
  {
    Outputs::RequireWritable(output.Path);
  }
  Outputs::RequireDistinct(options.OutputFiles(), options.InputFiles());
  if (options.Command == "render")
  {
    return RunRender(options);
  }
  if (options.Command == "reference")
  {
    return RunReference(options);
  }
  if (options.Command == "all")
  {
    return RunAll(options);
  }
  if (options.Command == "bench")
  {
    return RunBench(options);
  }
  if (options.Command == "shadow-bench")
  {
    return RunShadowBench(options);
  }
  if (options.Command == "report")
  {
    return RunReport(options);
  }
  if (options.Command == "view")
  {
    return RunView(options);
  }
  if (options.Command == "gallery")
  {
    return RunGallery(options);
  }
  if (options.Command == "presets")
  {
    return RunPresets(options);
  }
  if (options.Command == "series")
  {
    return RunSeries(options);
  }
  return RunScenes(options);
}
}

int main(int argc, char* argv[])
{
  using namespace deepshadow::tool;
  // A closed pipe on standard output, or a file-size limit (ulimit -f), is a write error
  // with its one line, not a signal.
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  try
  {
    const Options options = Options::Parse(argc, argv);
    RouteMessages(options.Verbose);
    const int code = Run(options);
    if (code != 2) // a refusal says its one line only
    {
      PrintModuleWarnings();
    }
    return code;
  }
  catch (const UsageError& error)
  {
    std::fprintf(stderr, "deepshadow: %s\n", OneLine(error.what()).c_str());
    return 2;
  }
  catch (const std::bad_alloc&)
  {
    // The budgets (Budget.h) refuse what is known to be too large before it is allocated;
    // this is what they did not foresee.
    std::fprintf(stderr, "deepshadow: out of memory (the input needs more than this machine or "
                         "its limits allow)\n");
    return 2;
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "deepshadow: %s\n", OneLine(error.what()).c_str());
    return 1;
  }
}
