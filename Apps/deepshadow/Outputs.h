// The files a command writes appear only when the command succeeds: each is written beside
// its destination under a temporary name and renamed into place by Commit(); a command that
// fails (throws) before that leaves nothing behind, and an existing file is not clobbered.
#ifndef deepshadow_tool_Outputs_h
#define deepshadow_tool_Outputs_h

#include <string>
#include <utility>
#include <vector>

namespace deepshadow
{
namespace tool
{

class Outputs
{
public:
  Outputs() = default;
  Outputs(const Outputs&) = delete;
  Outputs& operator=(const Outputs&) = delete;
  /** Removes the temporaries of a command that did not commit. */
  ~Outputs();

  /**
   * Throws UsageError unless a file can be created at `path` (its directory exists and is
   * writable, and `path` is not a directory). Cheap: call it before the work.
   */
  static void RequireWritable(const std::string& path);

  /** Where to write what is to become `path` (checked with RequireWritable). */
  std::string Stage(const std::string& path);

  /** Moves every staged file into place; throws UsageError if one cannot be. */
  void Commit();

private:
  std::vector<std::pair<std::string, std::string>> Staged; // temporary, destination
};

}
}
#endif
