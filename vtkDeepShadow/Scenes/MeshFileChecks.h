// Internal to DeepShadow::Scenes: checks of mesh files made before VTK's readers see them.
// VTK 9.1's PLY reader trusts the file: a truncated binary PLY, a header declaring 1e8
// vertices, a property before any element, a line with fewer values than its properties or
// a negative list count make it read past its buffers (SIGSEGV, or free() of a bad
// pointer); its OBJ reader follows corner indices unchecked; its binary STL reader silently
// reads the triangles of a truncated file that are there. Each check returns "" when it finds nothing wrong, else the problem in words.
#ifndef deepshadow_MeshFileChecks_h
#define deepshadow_MeshFileChecks_h

#include <cstdint>
#include <string>

namespace deepshadow
{
namespace meshfile
{

/**
 * A PLY file: its header (format, elements and their properties, known types, end_header)
 * and its body walked element by element (binary: every list count read and its items
 * within the file; ASCII: each element one line with the values its properties need).
 * `bytes` is set to an estimate of what VTK will allocate for it.
 */
std::string CheckPLY(const std::string& fileName, std::uint64_t& bytes);

/**
 * An OBJ file's face, line and point corners refer to vertices, texture coordinates and
 * normals declared before them (VTK's OBJ reader looks them up unchecked: a corner past
 * them crashes it or corrupts its heap). Relative (negative) indices are refused too.
 */
std::string CheckOBJ(const std::string& fileName, std::uint64_t& bytes);

/** A legacy VTK file starts with a version VTK 9.1 reads, a text title and ASCII or BINARY. */
std::string CheckLegacyVTK(const std::string& fileName);

/**
 * A VTK XML poly data file's counts (NumberOfPoints, ...Verts, ...Lines, ...Strips, ...Polys)
 * are whole numbers below 2^31 (VTK's reader allocates them unchecked: 2^63 crashed it).
 */
std::string CheckVTP(const std::string& fileName, std::uint64_t& bytes);

/** A binary STL file holds the triangles its header declares (ASCII STL: nothing to check). */
std::string CheckSTL(const std::string& fileName, std::uint64_t& bytes);

}
}
#endif
