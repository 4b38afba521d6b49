// Internal: a transfer function sampled into a table (deepshadow::TransferTable) and held as a
// 1-row RGBA float texture. The ray caster's table and a technique's feeler table are two of
// these, each with its own key of what it was sampled from. A label map's tables are one
// texture of a row per label (UpdateRows); a 2D transfer function is its image as given
// (UpdateImage).
#ifndef vtkDeepShadowTransferTableTexture_h
#define vtkDeepShadowTransferTableTexture_h

#include "Core/TransferFunction.h"

#include "vtkSmartPointer.h"

#include <glm/vec2.hpp>

#include <vector>

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace deepshadow
{

class TransferTableTexture
{
public:
  /** Whether the table held was sampled from anything else than what `key` names. */
  bool NeedsUpdate(const std::vector<double>& key) const { return !this->Texture || key != this->Key; }
  /** Samples `function` over `range` into `size` texels for `step`, uploads it, keeps `key`. */
  void Update(vtkOpenGLRenderWindow* window, const TransferFunction& function, const glm::dvec2& range,
    int size, double step, std::vector<double> key);
  /** Each of `functions` sampled over `range` into a row of `size` texels for a step of its
   * own unit distance (uncorrected), uploaded as one texture; keeps `key`. */
  void UpdateRows(vtkOpenGLRenderWindow* window, const std::vector<TransferFunction>& functions,
    const glm::dvec2& range, int size, std::vector<double> key);
  /** `width` x `height` RGBA float texels as given, uploaded; keeps `key`. */
  void UpdateImage(vtkOpenGLRenderWindow* window, int width, int height, const float* rgba, std::vector<double> key);
  void Release(vtkWindow* window);

  vtkTextureObject* GetTexture() const { return this->Texture; }
  const TransferTable& GetTable() const { return this->Table; }
  /** Bytes on the GPU: 4 floats a texel. */
  long long GetBytes() const { return static_cast<long long>(this->Table.Size) * 16 * this->Rows; }

private:
  vtkSmartPointer<vtkTextureObject> Texture;
  std::vector<double> Key;
  TransferTable Table; // UpdateRows: the first row's
  int Rows = 1;
};

}
#endif
