// The files a command writes appear only when the command succeeds, and never at the cost
// of the user's own files: each is written beside its destination under a temporary name
// (every byte checked: a full disk or a file-size limit is an error, not a short file) and
// renamed into place by Commit(); a command that fails (throws) before that leaves nothing
// behind. An output that is an input, the same file as another output, or an existing file
// that is not a regular file (a device, a pipe) is refused before any work; "-" and
// "/dev/stdout" name standard output, by the user's explicit choice.
#ifndef deepshadow_tool_Outputs_h
#define deepshadow_tool_Outputs_h

#include "Options.h"

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

  /** "-" and "/dev/stdout": standard output, written directly, never renamed over. */
  static bool IsStandardOutput(const std::string& path);

  /**
   * Throws UsageError unless a file can be created at `path`: its directory exists and is
   * writable, and `path` is not a directory nor any other existing file that is not a
   * regular file (writing there would replace a device node or a pipe with a file).
   * Cheap: call it before the work.
   */
  static void RequireWritable(const std::string& path);

  /**
   * Throws UsageError, before any work, if two outputs are the same file (the same path,
   * or the same existing file by device and inode: links), or if an output is one of the
   * `inputs` (which would be replaced by the picture).
   */
  static void RequireDistinct(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs);

  /**
   * Writes `bytes` to become `path` at Commit(): to a temporary file beside it now, every
   * write checked (throws UsageError naming `path`), or kept for standard output.
   */
  void Write(const std::string& path, const std::string& bytes);

  /** Moves every written file into place; throws UsageError if one cannot be. */
  void Commit();

private:
  std::vector<std::pair<std::string, std::string>> Staged; // temporary, destination
  std::vector<std::string> ToStandardOutput;
};

}
}
#endif
