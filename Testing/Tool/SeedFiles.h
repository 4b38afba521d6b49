// Well-formed small input files of every format the deepshadow tool reads, written with VTK's
// own writers (NRRD by hand: VTK 9.1 has no NRRD writer). The hostile-input tests break them
// on purpose (truncate, edit a header field) and the fuzz harness mutates them.
#ifndef deepshadow_testing_SeedFiles_h
#define deepshadow_testing_SeedFiles_h

#include <string>
#include <vector>

namespace deepshadow
{
namespace testing
{

struct SeedFile
{
  enum Kinds
  {
    Volume, // --volume
    Mesh    // --mesh or --bound
  };
  Kinds Kind;
  std::string Name;                    // in the directory, e.g. "volume.mhd"
  std::vector<std::string> Companions; // data files it names (e.g. "volume.raw"), copied along
};

/**
 * Writes the seeds into `directory` (which must exist): 16^3 volumes (a ball, unsigned char;
 * one float) as .vti (appended raw, zlib-compressed, inline base64), .mhd + .raw, .mha
 * (compressed), .nrrd (raw, gzip) and .nhdr + .raw; a sphere of 112 triangles as .ply
 * (binary, ASCII), .stl (binary, ASCII), .obj, .vtk and .vtp; and bound.obj, a closed cube
 * around the box scene at --scale 0.1. Returns them, in a fixed order.
 */
std::vector<SeedFile> WriteSeedFiles(const std::string& directory);

/** CSG expressions over two bounds, A and B, valid ones and nearly valid ones. */
std::vector<std::string> SeedExpressions();

}
}
#endif
