// deepshadow: the command-line tool of vtkDeepShadow. See `deepshadow --help`.
#include "Commands.h"
#include "Options.h"

#include "vtkObject.h"

#include <cstdio>
#include <exception>
#include <iostream>

int main(int argc, char* argv[])
{
  using namespace deepshadow::tool;
  try
  {
    const Options options = Options::Parse(argc, argv);
    // Errors reach the user as the tool's one line; VTK's own log only with --verbose.
    vtkObject::SetGlobalWarningDisplay(options.Verbose ? 1 : 0);
    if (options.Command == "help")
    {
      std::cout << Options::Usage();
      return 0;
    }
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
    return RunScenes(options);
  }
  catch (const UsageError& error)
  {
    std::fprintf(stderr, "deepshadow: %s\n", error.what());
    return 2;
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "deepshadow: %s\n", error.what());
    return 1;
  }
}
