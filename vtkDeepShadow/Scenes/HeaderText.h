// Internal to DeepShadow::Scenes, for the file checks (VolumeFileChecks, MeshFileChecks):
// whether a header line is text. VTK's text parsers read a NUL byte as the end of a line and
// then past the words they expected, or hang (a NUL in a NRRD header line made VTK 9.1's
// reader wait forever); other control bytes are as foreign to a header.
#ifndef deepshadow_HeaderText_h
#define deepshadow_HeaderText_h

#include <string>

namespace deepshadow
{
inline bool IsHeaderText(const std::string& line)
{
  for (char c : line)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if ((u < 32 && c != '\t' && c != '\r') || u == 127)
    {
      return false;
    }
  }
  return true;
}
}
#endif
