// What VTK and the module say while the tool runs. VTK's own log and messages are printed
// only with --verbose. The module's warnings (a node pool too small for the shadow, a layer
// count that loses it, a bound that encloses nothing, ...) say that a picture is not what was
// asked for, so they reach the user as "deepshadow: warning: ..." lines without --verbose
// too, each once, once the command is done, and a command's JSON lists them ("warnings"). A
// command refused (exit 2) prints its one line only.
#ifndef deepshadow_tool_Messages_h
#define deepshadow_tool_Messages_h

#include <string>
#include <vector>

namespace deepshadow
{
namespace tool
{

/**
 * `text` on one line: a line break or other control character (from a file name, a reader's
 * message) written as an escape (\n, \r, \t, \xHH), so that every message the tool prints
 * is one line.
 */
std::string OneLine(const std::string& text);

/** Routes VTK's messages as above; call once, before any work. */
void RouteMessages(bool verbose);

/** The module's warnings said so far, in order, each once. */
const std::vector<std::string>& ModuleWarnings();

/** Prints the module's warnings (without --verbose; VTK printed them with it). */
void PrintModuleWarnings();

/**
 * The message of a VTK warning text ("Warning: In FILE, line N\nCLASS (ADDRESS): MESSAGE")
 * from a class of the module (vtkDeepShadow...), on one line; empty for any other text.
 */
std::string ModuleWarningOf(const std::string& text);

}
}

#endif
