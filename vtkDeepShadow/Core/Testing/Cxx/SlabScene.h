// Shared by the Core unit tests: a volume with one slab in it, as a shadow caster.
#ifndef deepshadow_testing_SlabScene_h
#define deepshadow_testing_SlabScene_h

#include "Core/Shadows.h"
#include "Core/TransferFunction.h"
#include "Core/VolumeGrid.h"

#include <glm/mat4x4.hpp>

#include <memory>
#include <vector>

namespace deepshadow
{
namespace testing
{
// 21^3 points spanning [0, 20]^3; a slab of value 1 for z in [8, 12], 0 elsewhere.
struct SlabScene
{
  std::shared_ptr<VolumeGrid> Grid;
  TransferFunction Transfer;
  ShadowCaster Caster;

  explicit SlabScene(double slabOpacity)
  {
    std::vector<float> values(21 * 21 * 21, 0.0f);
    for (int k = 8; k <= 12; ++k)
      for (int j = 0; j < 21; ++j)
        for (int i = 0; i < 21; ++i)
          values[i + 21 * (j + 21 * k)] = 1.0f;
    this->Grid = std::make_shared<VolumeGrid>(glm::ivec3(21), values, glm::dmat4(1.0));
    // Opacity 0 for 0 and slabOpacity for 1, nearly a step so interpolation stays inside.
    this->Transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 0.999, 0.0 }, { 1.0, slabOpacity } });
    this->Caster.Grid = this->Grid.get();
    this->Caster.Transfer = &this->Transfer;
    this->Caster.Sampling = Interpolation::Nearest;
  }
};
}
}
#endif
