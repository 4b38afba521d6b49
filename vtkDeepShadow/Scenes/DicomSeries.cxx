#include "DicomSeries.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkType.h"

#include <gdcmImageReader.h>
#include <gdcmScanner.h>
#include <gdcmTrace.h>

#include <vtksys/Directory.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <sys/stat.h>

namespace deepshadow
{
namespace dicom
{
namespace
{
const gdcm::Tag SeriesUIDTag(0x0020, 0x000E), SeriesNumberTag(0x0020, 0x0011),
  DescriptionTag(0x0008, 0x103E), ModalityTag(0x0008, 0x0060), RowsTag(0x0028, 0x0010),
  ColumnsTag(0x0028, 0x0011), FramesTag(0x0028, 0x0008), PositionTag(0x0020, 0x0032),
  OrientationTag(0x0020, 0x0037), PixelSpacingTag(0x0028, 0x0030), SamplesTag(0x0028, 0x0002),
  BitsAllocatedTag(0x0028, 0x0100), BitsStoredTag(0x0028, 0x0101),
  RepresentationTag(0x0028, 0x0103), InterceptTag(0x0028, 0x1052), SlopeTag(0x0028, 0x1053),
  ImageTypeTag(0x0008, 0x0008);

std::string Trimmed(const char* value)
{
  std::string text = value ? value : "";
  const size_t first = text.find_first_not_of(" \t\r\n");
  const size_t last = text.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

// A DS or IS value's numbers (backslash-separated); empty when any is not a finite number.
std::vector<double> Numbers(const char* value)
{
  std::vector<double> numbers;
  std::stringstream parts(Trimmed(value));
  for (std::string part; std::getline(parts, part, '\\');)
  {
    char* end = nullptr;
    const double number = std::strtod(part.c_str(), &end);
    if (end == part.c_str() || !std::isfinite(number))
    {
      return {};
    }
    numbers.push_back(number);
  }
  return numbers;
}

double Number(const char* value, double fallback)
{
  const std::vector<double> numbers = Numbers(value);
  return numbers.size() == 1 ? numbers.front() : fallback;
}

std::string Name(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  return "'" + (slash == std::string::npos ? path : path.substr(slash + 1)) + "'";
}

// GDCM's messages while one lives, kept instead of printed (a reader says one line of its
// own); "Incomplete Pixel Data" among them means a file cut short, which GDCM reads anyway.
class GdcmMessages
{
public:
  GdcmMessages()
  {
    gdcm::Trace::SetDebugStream(this->Text);
    gdcm::Trace::SetWarningStream(this->Text);
    gdcm::Trace::SetErrorStream(this->Text);
  }
  ~GdcmMessages()
  {
    gdcm::Trace::SetDebugStream(std::cerr);
    gdcm::Trace::SetWarningStream(std::cerr);
    gdcm::Trace::SetErrorStream(std::cerr);
  }
  GdcmMessages(const GdcmMessages&) = delete;
  GdcmMessages& operator=(const GdcmMessages&) = delete;
  bool Said(const char* words) const { return this->Text.str().find(words) != std::string::npos; }
  void Clear() { this->Text.str(std::string()); }

private:
  std::ostringstream Text;
};

using Vector = std::array<double, 3>;

double Dot(const Vector& a, const Vector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vector Cross(const Vector& a, const Vector& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

bool Normalize(Vector& v)
{
  const double length = std::sqrt(Dot(v, v));
  if (!(length > 0.0))
  {
    return false;
  }
  for (double& c : v)
  {
    c /= length;
  }
  return true;
}

// The headers' values of one file that the geometry needs.
struct Slice
{
  std::string File;
  Vector Position{};
  std::array<double, 6> Orientation{};
  double RowSpacing = 0.0, ColumnSpacing = 0.0;
  double Slope = 1.0, Intercept = 0.0;
  double Along = 0.0; // position along the normal
};

// The VTK type that holds every stored value of `bits` bits (signed or not) rescaled by
// (slope, intercept): integers where both are whole, float otherwise.
int RescaledType(int bits, bool isSigned, double slope, double intercept)
{
  if (slope != std::floor(slope) || intercept != std::floor(intercept) || bits > 32 || bits < 1)
  {
    return VTK_FLOAT;
  }
  const double low = isSigned ? -std::ldexp(1.0, bits - 1) : 0.0;
  const double high = isSigned ? std::ldexp(1.0, bits - 1) - 1.0 : std::ldexp(1.0, bits) - 1.0;
  const double a = low * slope + intercept, b = high * slope + intercept;
  const double lo = std::min(a, b), hi = std::max(a, b);
  if (lo >= 0 && hi <= 255)
  {
    return VTK_UNSIGNED_CHAR;
  }
  if (lo >= -32768 && hi <= 32767)
  {
    return VTK_SHORT;
  }
  if (lo >= 0 && hi <= 65535)
  {
    return VTK_UNSIGNED_SHORT;
  }
  if (lo >= -2147483648.0 && hi <= 2147483647.0)
  {
    return VTK_INT;
  }
  return VTK_FLOAT;
}

// Element i of a decoded buffer holding values of type T; memcpy because GDCM's buffer
// carries no alignment promise.
template <typename T>
double Element(const char* buffer, size_t i)
{
  T v;
  std::memcpy(&v, buffer + sizeof(T) * i, sizeof(T));
  return static_cast<double>(v);
}

// Stored value i of a decoded buffer of GDCM scalar type `type`, as a double.
double Stored(const char* buffer, gdcm::PixelFormat::ScalarType type, size_t i)
{
  switch (type)
  {
    case gdcm::PixelFormat::UINT8:
      return Element<std::uint8_t>(buffer, i);
    case gdcm::PixelFormat::INT8:
      return Element<std::int8_t>(buffer, i);
    case gdcm::PixelFormat::UINT16:
      return Element<std::uint16_t>(buffer, i);
    case gdcm::PixelFormat::INT16:
      return Element<std::int16_t>(buffer, i);
    case gdcm::PixelFormat::UINT32:
      return Element<std::uint32_t>(buffer, i);
    case gdcm::PixelFormat::INT32:
      return Element<std::int32_t>(buffer, i);
    case gdcm::PixelFormat::FLOAT32:
      return Element<float>(buffer, i);
    case gdcm::PixelFormat::FLOAT64:
      return Element<double>(buffer, i);
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

size_t StoredBytes(gdcm::PixelFormat::ScalarType type)
{
  switch (type)
  {
    case gdcm::PixelFormat::UINT8:
    case gdcm::PixelFormat::INT8:
      return 1;
    case gdcm::PixelFormat::UINT16:
    case gdcm::PixelFormat::INT16:
      return 2;
    case gdcm::PixelFormat::UINT32:
    case gdcm::PixelFormat::INT32:
    case gdcm::PixelFormat::FLOAT32:
      return 4;
    case gdcm::PixelFormat::FLOAT64:
      return 8;
    default:
      return 0;
  }
}

// The geometry of a single multi-frame file, as GDCM's image gives it (per-frame functional
// groups of enhanced images included).
bool MultiFrameGeometry(const SeriesInfo& series, Geometry& geometry, std::string& problem)
{
  GdcmMessages quiet;
  gdcm::ImageReader reader;
  reader.SetFileName(series.Files.front().c_str());
  if (!reader.Read())
  {
    problem = Name(series.Files.front()) + ": GDCM cannot read it as an image";
    return false;
  }
  const gdcm::Image& image = reader.GetImage();
  const unsigned int* dims = image.GetDimensions();
  if (image.GetNumberOfDimensions() < 3 || dims[2] < 2)
  {
    problem = "the series is one slice; a volume needs at least 2";
    return false;
  }
  const double* cosines = image.GetDirectionCosines();
  Vector row{ cosines[0], cosines[1], cosines[2] }, column{ cosines[3], cosines[4], cosines[5] };
  Vector normal = Cross(row, column);
  if (!Normalize(row) || !Normalize(column) || !Normalize(normal))
  {
    problem = Name(series.Files.front()) + ": its image orientation is not two directions";
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    geometry.Dimensions[a] = static_cast<int>(dims[a]);
    geometry.Spacing[a] = image.GetSpacing()[a];
    geometry.Origin[a] = image.GetOrigin()[a];
    geometry.Direction[3 * a] = row[static_cast<size_t>(a)];
    geometry.Direction[3 * a + 1] = column[static_cast<size_t>(a)];
    geometry.Direction[3 * a + 2] = normal[static_cast<size_t>(a)];
  }
  const gdcm::PixelFormat& format = image.GetPixelFormat();
  geometry.ScalarType = RescaledType(format.GetBitsStored(), format.GetPixelRepresentation() != 0,
    image.GetSlope(), image.GetIntercept());
  geometry.Files = series.Files;
  return true;
}

// What the slices' headers say of their pixels: the image size, which every slice must share,
// and the widest stored value (bits, signedness) of any slice, which the scalar type must hold.
struct PixelLayout
{
  int Rows = 0, Columns = 0, Bits = 0, Signed = 0;
};

// The volume's directions: the slices' row and column, the normal of their planes, and the
// step from one slice to the next (along the normal unless the slices are sheared).
struct Axes
{
  Vector Row{}, Column{}, Normal{}, Step{};
  double StepLength = 0.0;
};

// One file's header as a slice, and its pixel layout. False with `problem` for what cannot be
// a slice of a volume: a mosaic, no position or orientation, several samples a pixel.
bool ReadSlice(const gdcm::Scanner& scanner, const std::string& file, Slice& slice,
  PixelLayout& layout, std::string& problem)
{
  const char* f = file.c_str();
  if (Trimmed(scanner.GetValue(f, ImageTypeTag)).find("MOSAIC") != std::string::npos)
  {
    problem = Name(file) + ": a Siemens mosaic (a volume's slices tiled in one image); convert "
      "the series with dcm2niix and read its NIfTI";
    return false;
  }
  slice.File = file;
  const std::vector<double> position = Numbers(scanner.GetValue(f, PositionTag));
  const std::vector<double> orientation = Numbers(scanner.GetValue(f, OrientationTag));
  const std::vector<double> spacing = Numbers(scanner.GetValue(f, PixelSpacingTag));
  if (position.size() != 3 || orientation.size() != 6)
  {
    problem = Name(file) + ": no ImagePositionPatient and ImageOrientationPatient (it cannot be "
      "placed in a volume)";
    return false;
  }
  std::copy(position.begin(), position.end(), slice.Position.begin());
  std::copy(orientation.begin(), orientation.end(), slice.Orientation.begin());
  slice.RowSpacing = spacing.size() == 2 ? spacing[0] : 1.0;
  slice.ColumnSpacing = spacing.size() == 2 ? spacing[1] : 1.0;
  slice.Slope = Number(scanner.GetValue(f, SlopeTag), 1.0);
  slice.Intercept = Number(scanner.GetValue(f, InterceptTag), 0.0);
  const int samples = static_cast<int>(Number(scanner.GetValue(f, SamplesTag), 1));
  if (samples != 1)
  {
    problem = Name(file) + ": " + std::to_string(samples) +
      " samples a pixel (colour): a volume here holds one value a voxel";
    return false;
  }
  layout.Rows = static_cast<int>(Number(scanner.GetValue(f, RowsTag), 0));
  layout.Columns = static_cast<int>(Number(scanner.GetValue(f, ColumnsTag), 0));
  layout.Bits = static_cast<int>(Number(scanner.GetValue(f, BitsStoredTag), 16));
  layout.Signed = static_cast<int>(Number(scanner.GetValue(f, RepresentationTag), 0));
  return true;
}

// Adds the layout of the slice `file` to the series' (`slices`: those read before it): the
// first sets it; the others must share its size and may widen its values.
bool AddLayout(const std::vector<Slice>& slices, const std::string& file,
  const PixelLayout& own, PixelLayout& layout, std::string& problem)
{
  if (slices.empty())
  {
    layout = own;
  }
  else if (own.Rows != layout.Rows || own.Columns != layout.Columns)
  {
    problem = "the series mixes image sizes: " + Name(slices.front().File) + " is " +
      std::to_string(layout.Columns) + "x" + std::to_string(layout.Rows) + ", " + Name(file) +
      " " + std::to_string(own.Columns) + "x" + std::to_string(own.Rows);
    return false;
  }
  else
  {
    layout.Bits = std::max(layout.Bits, own.Bits);
    layout.Signed = std::max(layout.Signed, own.Signed);
  }
  return true;
}

// Every file's header as a slice, in the series' file order, with their common layout.
bool ReadSlices(const SeriesInfo& series, std::vector<Slice>& slices, PixelLayout& layout,
  std::string& problem)
{
  GdcmMessages quiet;
  gdcm::Scanner scanner;
  for (const gdcm::Tag& tag : { RowsTag, ColumnsTag, PositionTag, OrientationTag, PixelSpacingTag,
         SamplesTag, BitsStoredTag, RepresentationTag, InterceptTag, SlopeTag, ImageTypeTag })
  {
    scanner.AddTag(tag);
  }
  scanner.Scan(series.Files);
  for (const std::string& file : series.Files)
  {
    Slice slice;
    PixelLayout own;
    if (!ReadSlice(scanner, file, slice, own, problem) ||
      !AddLayout(slices, file, own, layout, problem))
    {
      return false;
    }
    slices.push_back(slice);
  }
  return true;
}

// One orientation and pixel spacing for all: each slice against the first in file order.
bool CheckOneOrientationAndSpacing(const std::vector<Slice>& slices, std::string& problem)
{
  const Slice& first = slices.front();
  for (const Slice& slice : slices)
  {
    for (size_t i = 0; i < 6; ++i)
    {
      if (std::abs(slice.Orientation[i] - first.Orientation[i]) > 1e-3)
      {
        problem = "the series mixes image orientations (" + Name(first.File) + " and " +
          Name(slice.File) + "): not one volume";
        return false;
      }
    }
    if (std::abs(slice.RowSpacing - first.RowSpacing) > 1e-4 * first.RowSpacing ||
      std::abs(slice.ColumnSpacing - first.ColumnSpacing) > 1e-4 * first.ColumnSpacing)
    {
      problem = "the series mixes pixel spacings (" + Name(first.File) + " and " +
        Name(slice.File) + "): not one volume";
      return false;
    }
  }
  return true;
}

// The row and column directions of `first`'s ImageOrientationPatient and their normal.
bool PlaneAxes(const Slice& first, Axes& axes, std::string& problem)
{
  axes.Row = { first.Orientation[0], first.Orientation[1], first.Orientation[2] };
  axes.Column = { first.Orientation[3], first.Orientation[4], first.Orientation[5] };
  axes.Normal = Cross(axes.Row, axes.Column);
  if (!Normalize(axes.Row) || !Normalize(axes.Column) || !Normalize(axes.Normal))
  {
    problem = Name(first.File) + ": its ImageOrientationPatient is not two directions";
    return false;
  }
  return true;
}

// Orders the slices by their position along the normal of their planes.
void SortAlongNormal(std::vector<Slice>& slices, const Vector& normal)
{
  for (Slice& slice : slices)
  {
    slice.Along = Dot(slice.Position, normal);
  }
  std::stable_sort(slices.begin(), slices.end(), [](const Slice& a, const Slice& b) { return a.Along < b.Along; });
}

// The sorted slices' gaps along the normal: none empty (two slices at one position are several
// volumes), and all alike (else slices are missing, or the acquisition was uneven).
bool CheckEvenGaps(const std::vector<Slice>& slices, std::string& problem)
{
  const size_t n = slices.size();
  const double extent = slices.back().Along - slices.front().Along;
  const double step = extent / static_cast<double>(n - 1);
  double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (size_t k = 0; k + 1 < n; ++k)
  {
    const double gap = slices[k + 1].Along - slices[k].Along;
    if (gap < 1e-3)
    {
      problem = "slices " + Name(slices[k].File) + " and " + Name(slices[k + 1].File) +
        " lie at the same position: several volumes in one series (echoes, phases or times?)";
      return false;
    }
    smallest = std::min(smallest, gap);
    largest = std::max(largest, gap);
  }
  if (largest - smallest > 0.01 * step + 1e-3)
  {
    std::ostringstream text;
    text << "its slices are unevenly spaced (gaps of " << smallest << " to " << largest
         << " mm along the normal): not one volume; resample it, or give a series of even spacing";
    problem = text.str();
    return false;
  }
  return true;
}

// The third axis: from the first slice's position to the last's, a step a slice. Along the
// normal, unless the slices are sheared (gantry tilt): then off it, each slice still at its
// own position (the direction matrix is not orthogonal; nothing is resampled). False when a
// slice is off that line.
bool StepAxis(const std::vector<Slice>& slices, Axes& axes, std::string& problem)
{
  const size_t n = slices.size();
  const Slice& origin = slices.front();
  for (size_t a = 0; a < 3; ++a)
  {
    axes.Step[a] = (slices.back().Position[a] - origin.Position[a]) / static_cast<double>(n - 1);
  }
  axes.StepLength = std::sqrt(Dot(axes.Step, axes.Step));
  for (size_t k = 0; k < n; ++k)
  {
    double off = 0.0;
    for (size_t a = 0; a < 3; ++a)
    {
      const double expected = origin.Position[a] + static_cast<double>(k) * axes.Step[a];
      off = std::max(off, std::abs(slices[k].Position[a] - expected));
    }
    if (off > 0.01 * axes.StepLength + 1e-3)
    {
      problem = "its slices do not lie on one line at even steps (" + Name(slices[k].File) +
        " is " + std::to_string(off) + " mm off it): not one volume";
      return false;
    }
  }
  return true;
}

// Says a gantry tilt in the geometry's warning: the reader reads the series, but the volume's
// third axis is not the normal of its slices.
void WarnOfShear(const Axes& axes, Geometry& geometry)
{
  const double shear =
    std::acos(std::min(1.0, std::abs(Dot(axes.Step, axes.Normal)) / axes.StepLength)) * 180.0 / M_PI;
  if (shear > 0.01)
  {
    std::ostringstream text;
    text << "its slices are sheared by " << shear << " degrees off the normal of their planes "
         << "(gantry tilt): each is placed at its own position, the volume's third axis "
         << "following them (not resampled)";
    geometry.Warning = text.str();
  }
}

// Places the volume of the sorted, checked slices: origin, spacing and directions from the
// first slice along the normal (its pixel spacing and rescale among them), files in slice
// order. Float values when the slices are rescaled differently.
void PlaceVolume(const std::vector<Slice>& slices, const PixelLayout& layout, const Axes& axes,
  Geometry& geometry)
{
  const Slice& first = slices.front();
  double slope = first.Slope, intercept = first.Intercept;
  bool oneRescale = true;
  for (const Slice& slice : slices)
  {
    geometry.Files.push_back(slice.File);
    oneRescale = oneRescale && slice.Slope == slope && slice.Intercept == intercept;
  }
  geometry.Dimensions[0] = layout.Columns;
  geometry.Dimensions[1] = layout.Rows;
  geometry.Dimensions[2] = static_cast<int>(slices.size());
  geometry.Spacing[0] = first.ColumnSpacing;
  geometry.Spacing[1] = first.RowSpacing;
  geometry.Spacing[2] = axes.StepLength;
  for (size_t a = 0; a < 3; ++a)
  {
    geometry.Origin[a] = first.Position[a];
    geometry.Direction[3 * a] = axes.Row[a];
    geometry.Direction[3 * a + 1] = axes.Column[a];
    geometry.Direction[3 * a + 2] = axes.Step[a] / axes.StepLength;
  }
  geometry.ScalarType =
    oneRescale ? RescaledType(layout.Bits, layout.Signed != 0, slope, intercept) : VTK_FLOAT;
}
}

std::vector<std::string> RegularFiles(const std::string& directory, std::string* problem)
{
  vtksys::Directory listing;
  std::vector<std::string> files;
  if (!listing.Load(directory))
  {
    if (problem)
    {
      *problem = "cannot list the directory";
    }
    return files;
  }
  for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
  {
    const std::string name = listing.GetFile(i);
    const std::string path = directory + "/" + name;
    struct stat info;
    if (name == "." || name == ".." || (stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)))
    {
      continue;
    }
    if (stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode))
    {
      if (problem && problem->empty())
      {
        *problem = "'" + name + "' in the directory is not a regular file (a pipe, device or "
          "broken link; a reader would open it and could wait for ever)";
      }
      continue;
    }
    files.push_back(path);
  }
  std::sort(files.begin(), files.end());
  return files;
}

int NarrowestType(vtkDataArray* values)
{
  const int type = values->GetDataType();
  if (type == VTK_FLOAT || type == VTK_DOUBLE || values->GetNumberOfTuples() == 0)
  {
    return type;
  }
  double range[2];
  values->GetRange(range, 0);
  return range[0] >= 0 && range[1] <= 255  ? VTK_UNSIGNED_CHAR
    : range[0] >= -32768 && range[1] <= 32767 ? VTK_SHORT
    : range[0] >= 0 && range[1] <= 65535      ? VTK_UNSIGNED_SHORT
                                              : type;
}

bool IsDicomFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  char magic[4] = { 0, 0, 0, 0 };
  return in.seekg(128) && in.read(magic, 4) && std::string(magic, 4) == "DICM";
}

std::vector<SeriesInfo> ListSeries(const std::vector<std::string>& files, std::string& problem)
{
  GdcmMessages quiet;
  gdcm::Scanner scanner;
  for (const gdcm::Tag& tag : { SeriesUIDTag, SeriesNumberTag, DescriptionTag, ModalityTag, RowsTag,
         ColumnsTag, FramesTag })
  {
    scanner.AddTag(tag);
  }
  // Only files with DICOM's preamble reach GDCM: it would try to parse anything else.
  gdcm::Directory::FilenamesType dicom;
  for (const std::string& file : files)
  {
    if (IsDicomFile(file))
    {
      dicom.push_back(file);
    }
  }
  std::vector<SeriesInfo> series;
  if (dicom.empty() || !scanner.Scan(dicom))
  {
    problem = "no DICOM files in the directory (" + std::to_string(files.size()) +
      " files, none with DICOM's \"DICM\" preamble)";
    return series;
  }
  std::map<std::string, size_t> index;
  for (const std::string& file : dicom)
  {
    const int rows = static_cast<int>(Number(scanner.GetValue(file.c_str(), RowsTag), 0));
    const int columns = static_cast<int>(Number(scanner.GetValue(file.c_str(), ColumnsTag), 0));
    if (!scanner.IsKey(file.c_str()) || rows <= 0 || columns <= 0)
    {
      continue; // not an image (a DICOMDIR, a report, a structure set)
    }
    const std::string uid = Trimmed(scanner.GetValue(file.c_str(), SeriesUIDTag));
    auto found = index.find(uid);
    if (found == index.end())
    {
      found = index.emplace(uid, series.size()).first;
      SeriesInfo info;
      info.UID = uid;
      info.Number = Trimmed(scanner.GetValue(file.c_str(), SeriesNumberTag));
      info.Description = Trimmed(scanner.GetValue(file.c_str(), DescriptionTag));
      info.Modality = Trimmed(scanner.GetValue(file.c_str(), ModalityTag));
      info.Rows = rows;
      info.Columns = columns;
      series.push_back(info);
    }
    SeriesInfo& info = series[found->second];
    info.Files.push_back(file);
    info.Frames += static_cast<std::uint64_t>(std::max(1.0, Number(scanner.GetValue(file.c_str(), FramesTag), 1.0)));
  }
  if (series.empty())
  {
    problem = "no DICOM images in the directory (" + std::to_string(dicom.size()) +
      " DICOM files, none with rows and columns)";
  }
  std::stable_sort(series.begin(), series.end(), [](const SeriesInfo& a, const SeriesInfo& b) {
    const double na = Number(a.Number.c_str(), 1e300), nb = Number(b.Number.c_str(), 1e300);
    return na != nb ? na < nb : a.UID < b.UID;
  });
  return series;
}

std::string Describe(const SeriesInfo& series)
{
  std::ostringstream text;
  text << (series.Number.empty() ? std::string("?") : series.Number) << " ("
       << (series.Modality.empty() ? std::string("no modality") : series.Modality) << ", '"
       << series.Description << "', " << series.Frames << (series.Frames == 1 ? " slice" : " slices")
       << " of " << series.Columns << "x" << series.Rows << ", UID " << series.UID << ")";
  return text.str();
}

const SeriesInfo* Choose(const std::vector<SeriesInfo>& series, const std::string& choice, std::string& problem)
{
  if (choice.empty() && series.size() == 1)
  {
    return &series.front();
  }
  const SeriesInfo* byNumber = nullptr;
  int numbered = 0;
  for (const SeriesInfo& s : series)
  {
    if (!choice.empty() && s.UID == choice)
    {
      return &s;
    }
    if (!choice.empty() && s.Number == choice)
    {
      byNumber = &s;
      ++numbered;
    }
  }
  if (numbered == 1)
  {
    return byNumber;
  }
  std::string list;
  for (const SeriesInfo& s : series)
  {
    list += (list.empty() ? "" : "; ") + Describe(s);
  }
  problem = (choice.empty() ? "the directory holds " + std::to_string(series.size()) +
                  " series; choose one by its number or UID (--series, SetSeries): "
      : numbered > 1       ? std::to_string(numbered) + " series are numbered " + choice +
                  "; choose one by its UID: "
                           : "no series '" + choice + "' in the directory; its series: ") + list;
  return nullptr;
}

bool ReadGeometry(const SeriesInfo& series, Geometry& geometry, std::string& problem)
{
  geometry = Geometry();
  geometry.Modality = series.Modality;
  if (series.Files.size() == 1 && series.Frames > 1)
  {
    return MultiFrameGeometry(series, geometry, problem);
  }
  if (series.Frames != series.Files.size())
  {
    problem = "the series mixes multi-frame files with others, or holds several multi-frame files";
    return false;
  }
  if (series.Files.size() < 2)
  {
    problem = "the series is one slice; a volume needs at least 2";
    return false;
  }
  std::vector<Slice> slices;
  PixelLayout layout;
  Axes axes;
  // The planes' directions come from the first slice in file order, before sorting.
  if (!ReadSlices(series, slices, layout, problem) ||
    !CheckOneOrientationAndSpacing(slices, problem) || !PlaneAxes(slices.front(), axes, problem))
  {
    return false;
  }
  SortAlongNormal(slices, axes.Normal);
  if (!CheckEvenGaps(slices, problem) || !StepAxis(slices, axes, problem))
  {
    return false;
  }
  WarnOfShear(axes, geometry);
  PlaceVolume(slices, layout, axes, geometry);
  return true;
}

bool ReadPixels(const Geometry& geometry, vtkImageData* image, std::string& problem)
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const size_t sliceVoxels = static_cast<size_t>(geometry.Dimensions[0]) * static_cast<size_t>(geometry.Dimensions[1]);
  size_t next = 0; // the first voxel of the next slice to fill
  GdcmMessages messages;
  for (const std::string& file : geometry.Files)
  {
    messages.Clear();
    gdcm::ImageReader reader;
    reader.SetFileName(file.c_str());
    if (!reader.Read() || messages.Said("Incomplete Pixel Data"))
    {
      problem = Name(file) + (messages.Said("Incomplete Pixel Data")
          ? std::string(": its pixel data is cut short (truncated?)")
          : std::string(": GDCM cannot read its image (a transfer syntax it does not decode, or a "
                        "damaged file)"));
      return false;
    }
    const gdcm::Image& slice = reader.GetImage();
    const unsigned int* dims = slice.GetDimensions();
    const size_t frames = slice.GetNumberOfDimensions() > 2 ? dims[2] : 1;
    const gdcm::PixelFormat::ScalarType type = slice.GetPixelFormat().GetScalarType();
    const size_t bytes = StoredBytes(type);
    if (static_cast<int>(dims[0]) != geometry.Dimensions[0] || static_cast<int>(dims[1]) != geometry.Dimensions[1] ||
      slice.GetPixelFormat().GetSamplesPerPixel() != 1 || bytes == 0)
    {
      problem = Name(file) + ": its image is not the " + std::to_string(geometry.Dimensions[0]) + "x" +
        std::to_string(geometry.Dimensions[1]) + " single-value image its header declares";
      return false;
    }
    const size_t voxels = sliceVoxels * frames;
    std::vector<char> buffer(slice.GetBufferLength());
    if (buffer.size() < voxels * bytes || !slice.GetBuffer(buffer.data()))
    {
      problem = Name(file) + ": GDCM could not decode its pixel data (cut short, or damaged)";
      return false;
    }
    if (next + voxels > static_cast<size_t>(scalars->GetNumberOfTuples()))
    {
      problem = Name(file) + ": more frames than the series' headers declare";
      return false;
    }
    const double slope = slice.GetSlope(), intercept = slice.GetIntercept();
    for (size_t i = 0; i < voxels; ++i)
    {
      scalars->SetComponent(static_cast<vtkIdType>(next + i), 0, Stored(buffer.data(), type, i) * slope + intercept);
    }
    next += voxels;
  }
  scalars->Modified();
  return true;
}

}
}
