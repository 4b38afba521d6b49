// Internal to DeepShadow::Scenes: what the file readers hear from the VTK readers they
// delegate to. Errors and warnings arrive as events on observers attached to each delegate
// (never through VTK's output window; VTK's global warning switch is held on while a delegate
// runs, because in VTK 9.1 it also gates the events), and what MetaIO and similar libraries
// print to std::cerr is captured while a delegate runs, so that a reader can report one
// clear line whatever the application set.
#ifndef deepshadow_ReaderMessages_h
#define deepshadow_ReaderMessages_h

#include "vtkCommand.h"

#include <iosfwd>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

class vtkAlgorithm;

namespace deepshadow
{
namespace reader
{

/** "ERROR: In file, line N\nvtkClass (0x...): text\n\n" -> "text", on one line. */
std::string OneLine(const char* message);

/**
 * Collects the error and warning events of a delegate reader (and of its executive, and of
 * an XML reader's parser) instead of letting them print.
 */
class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  vtkTypeMacro(ErrorCollector, vtkCommand);

  void Execute(vtkObject* caller, unsigned long event, void* callData) override;

  /** Observes `reader`'s errors and warnings, its executive's and its XML parser's. */
  void Watch(vtkAlgorithm* reader);

  void Clear();
  bool Failed() const { return !this->Errors.empty() || this->ExecutiveFailed; }
  /** The first error, else `fallback`. */
  std::string Reason(const std::string& fallback) const;

  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
  bool ExecutiveFailed = false;
};

/**
 * While alive, VTK's global warning display is on, whatever the application set: in VTK 9.1
 * it also gates error and warning events, so a delegate's errors would not reach the
 * collector. Nothing is printed by it: the delegate's events go to the collector.
 */
class WarningDisplayOn
{
public:
  WarningDisplayOn();
  ~WarningDisplayOn();
  WarningDisplayOn(const WarningDisplayOn&) = delete;
  WarningDisplayOn& operator=(const WarningDisplayOn&) = delete;

private:
  int Saved;
};

/**
 * While alive, what is written to std::cerr goes into Lines() instead (MetaIO prints its
 * errors there, e.g. "Uncompress failed").
 */
class CerrCapture
{
public:
  CerrCapture();
  ~CerrCapture();
  CerrCapture(const CerrCapture&) = delete;
  CerrCapture& operator=(const CerrCapture&) = delete;
  /** The non-empty lines written so far. */
  std::vector<std::string> Lines() const;

private:
  std::ostringstream Text;
  std::streambuf* Saved;
};

}
}
#endif
