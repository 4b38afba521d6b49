#include "Messages.h"

#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"

#include <algorithm>
#include <cstdio>

namespace deepshadow
{
namespace tool
{
namespace
{
std::vector<std::string> Said;
bool Verbose = false;

// Only the printing of VTK's messages is switched off without --verbose: VTK's global
// warning flag stays on, because in VTK 9.1 it also gates the error events that the readers'
// collectors listen to, so the exit code and the line never depend on --verbose.
class ToolOutputWindow : public vtkOutputWindow
{
public:
  static ToolOutputWindow* New();
  vtkTypeMacro(ToolOutputWindow, vtkOutputWindow);

  void DisplayWarningText(const char* text) override
  {
    const std::string message = ModuleWarningOf(text ? text : "");
    if (!message.empty() && std::find(Said.begin(), Said.end(), message) == Said.end())
    {
      Said.push_back(message);
    }
    this->Superclass::DisplayWarningText(text);
  }
};
vtkStandardNewMacro(ToolOutputWindow);
}

std::string OneLine(const std::string& text)
{
  std::string line;
  for (const char c : text)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '\n' || c == '\r' || c == '\t')
    {
      line += c == '\n' ? "\\n" : c == '\r' ? "\\r" : "\\t";
    }
    else if (u < 32 || u == 127)
    {
      char escape[5];
      std::snprintf(escape, sizeof(escape), "\\x%02x", u);
      line += escape;
    }
    else
    {
      line += c;
    }
  }
  return line;
}

void RouteMessages(bool verbose)
{
  vtkNew<ToolOutputWindow> window;
  Verbose = verbose;
  if (!verbose)
  {
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    window->SetDisplayModeToNever();
  }
  vtkOutputWindow::SetInstance(window);
}

const std::vector<std::string>& ModuleWarnings()
{
  return Said;
}

void PrintModuleWarnings()
{
  if (Verbose)
  {
    return;
  }
  for (const std::string& message : Said)
  {
    std::fprintf(stderr, "deepshadow: warning: %s\n", OneLine(message).c_str());
  }
}

std::string ModuleWarningOf(const std::string& text)
{
  const size_t line = text.find('\n');
  const size_t start = line == std::string::npos ? 0 : line + 1;
  const std::string module = "vtkDeepShadow"; // the module's class names begin so
  if (text.compare(start, module.size(), module) != 0)
  {
    return std::string();
  }
  const size_t sender = text.find("): ", start);
  if (sender == std::string::npos)
  {
    return std::string();
  }
  std::string message = text.substr(sender + 3);
  std::replace(message.begin(), message.end(), '\n', ' ');
  message.erase(message.find_last_not_of(' ') + 1);
  return message;
}

}
}
