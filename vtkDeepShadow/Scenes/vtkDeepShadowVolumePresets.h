/**
 * @class   vtkDeepShadowVolumePresets
 * @brief   Loads a named CT/MR transfer-function preset or a ParaView preset file into a
 *          vtkVolumeProperty with one call.
 *
 * Named presets (GetPresetNames(); `deepshadow presets` lists them): CT-Bone, CT-Skin,
 * CT-Muscle, CT-Soft-Tissue, CT-Lung (Hounsfield units), MR-Default, MR-Angio (intensity, as
 * 3D Slicer's MR presets: an unsigned range of a few hundred). Except CT-Skin, the values are
 * those of 3D Slicer's volume rendering presets (scalar opacity, colour, ambient, diffuse,
 * specular, shading) that ParaView users also know by these names.
 *
 * Files: ParaView's JSON preset format, as "Save preset" writes it: a list of objects (or one
 * object) with "RGBPoints" (x, r, g, b, ...), optionally "Points" (scalar opacity: x, opacity,
 * midpoint, sharpness, ...), "ColorSpace" (RGB, HSV, Lab, Diverging) and "Name"; the first
 * object, or the one SetPresetName() names. A file with no opacity keeps the property's.
 *
 * SetWindowLevel(W, L) maps the preset's interval of interest (its opacity nodes without the
 * two ends; for a file, its opacity or colour nodes) linearly onto [L - W/2, L + W/2].
 *
 * Bad input (an unknown name, a missing, oversized or malformed file, a non-finite or out of
 * range value, decreasing x, a count that is not a multiple of 4) is one vtkErrorMacro line,
 * also kept in GetLastError(); the property is then left unchanged.
 */
#ifndef vtkDeepShadowVolumePresets_h
#define vtkDeepShadowVolumePresets_h

#include "vtkDeepShadowScenesModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string
#include <vector> // For std::vector

class vtkImageData;
class vtkVolumeProperty;

class VTKDEEPSHADOWSCENES_EXPORT vtkDeepShadowVolumePresets : public vtkObject
{
public:
  static vtkDeepShadowVolumePresets* New();
  vtkTypeMacro(vtkDeepShadowVolumePresets, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The named presets, and one line on each (modality, units, what it shows). */
  static std::vector<std::string> GetPresetNames();
  static std::string GetPresetDescription(const std::string& name);
  /** Case-insensitive, as every lookup here. */
  static bool IsPresetName(const std::string& name);

  /** Loads the named preset into `property`; false (and an error) for an unknown name. */
  bool ApplyPreset(const std::string& name, vtkVolumeProperty* property);
  /** Loads a ParaView JSON preset file into `property`. */
  bool ApplyFile(const std::string& path, vtkVolumeProperty* property);
  /** A preset name, or else a file path: what `--tf` takes. */
  bool Apply(const std::string& nameOrPath, vtkVolumeProperty* property);

  /**
   * The look a medical volume gets when none is given, by its modality: CT-Bone for CT (the
   * modality "CT", or values in Hounsfield units: air near -1000); else MR-Default, its
   * interval mapped from Otsu's threshold between background and tissue to the data's
   * 99.5th percentile (MR intensities have no fixed scale). Returns what was chosen, e.g.
   * "MR-Default, window 146 level 92"; "" with an error for an image with no finite values.
   */
  std::string ApplyDefault(const std::string& modality, vtkImageData* image, vtkVolumeProperty* property);

  /**
   * A warning when a preset made for another scale meets `image`: a CT preset on values that
   * are not Hounsfield units (no air near -1000 HU) shows nothing of it or a solid box; ""
   * when it fits (or for files, whose scale is their own).
   */
  static std::string DataWarning(const std::string& preset, vtkImageData* image);

  ///@{
  /** The preset of a file with several to use (by "Name"); empty: the first. */
  vtkSetMacro(PresetName, std::string);
  vtkGetMacro(PresetName, std::string);
  ///@}

  ///@{
  /** Window and level (in the data's units) the preset's interval is mapped onto. */
  void SetWindowLevel(double window, double level);
  void ClearWindowLevel();
  vtkGetMacro(Window, double);
  vtkGetMacro(Level, double);
  bool HasWindowLevel() const { return this->UseWindowLevel; }
  ///@}

  /**
   * Nodes a file's "RGBPoints" or "Points" may hold: VTK 9.1 sorts a function's nodes again
   * at each one added, so loading n takes time quadratic in n (4096: 0.1 s here; 20,000:
   * 3.3 s; 200,000 would take minutes). ParaView's presets hold at most a few hundred.
   */
  static constexpr int MaximumNodes = 4096;

  /**
   * The narrowest window SetWindowLevel takes: MinimumRelativeWindow of |level|, and at least
   * MinimumWindow (narrower, the preset's nodes merge where doubles and the GPU's floats can no
   * longer tell them apart: at 1e-100 the whole volume became opaque).
   */
  static constexpr double MinimumRelativeWindow = 1e-6;
  static constexpr double MinimumWindow = 1e-30;

  /** Files larger than this are refused; no more than this is read (default 16 MiB). */
  vtkSetClampMacro(MaximumFileBytes, double, 1.0, 1.0e9);
  vtkGetMacro(MaximumFileBytes, double);

  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkDeepShadowVolumePresets() = default;
  ~vtkDeepShadowVolumePresets() override = default;

  bool Fail(const std::string& message);

  std::string PresetName;
  double Window = 0.0;
  double Level = 0.0;
  bool UseWindowLevel = false;
  double MaximumFileBytes = 16.0 * 1024.0 * 1024.0;
  std::string LastError;

private:
  vtkDeepShadowVolumePresets(const vtkDeepShadowVolumePresets&) = delete;
  void operator=(const vtkDeepShadowVolumePresets&) = delete;
};

#endif
