// A technique's parameters as text, "KEY=VALUE KEY=VALUE" with the tool's option names: what
// ParaView's ShadowParameters property holds, read by the representation and edited field by
// field by the plugin's parameter form.
#ifndef deepshadow_ShadowParameterText_h
#define deepshadow_ShadowParameterText_h

#include "vtkDeepShadowCoreModule.h"

#include <string>
#include <utility>
#include <vector>

namespace deepshadow
{

/**
 * The KEY=VALUE pairs of `text`, in order. Pairs are separated by spaces, tabs, newlines or
 * commas; a piece without '=' continues the previous value (opacity-levels=0.1,0.5,0.9).
 * Throws std::invalid_argument("shadow parameter 'PIECE' has no value (KEY=VALUE)") for a
 * piece without '=' that no pair precedes.
 */
VTKDEEPSHADOWCORE_EXPORT std::vector<std::pair<std::string, std::string>> SplitShadowParameterText(
  const std::string& text);

/**
 * `text` with `key` set to `value`: its pair replaced where it was, or appended; an empty
 * value removes it. The pairs come back separated by single spaces.
 */
VTKDEEPSHADOWCORE_EXPORT std::string SetShadowParameterInText(
  const std::string& text, const std::string& key, const std::string& value);

}
#endif
