/**
 * @class   vtkDeepShadowBrickExchange
 * @brief   How the bricks of one volume, drawn by several processes, share their shadows.
 *
 * Under `mpirun -np N pvbatch` each rank draws one brick of a volume, and IceT composites the
 * pictures. A light-space technique (shadow map, deep shadow map, opacity levels, stochastic
 * shadow map, and their cached variants) given an exchange with more than one brick:
 *   1. fits its light faces to the union of every brick's box, so that texels line up across
 *      ranks;
 *   2. after building its maps, reads each texel's total transmittance through its own brick
 *      (its lookup at the far end of the texel's ray);
 *   3. gathers every brick's totals and multiplies, per texel, those of the bricks that lie
 *      between it and the light (deepshadow::UpstreamTransmittance) into its lookups.
 * Both gathers are collective: every brick's mapper must draw every frame (ParaView's view
 * does; a rank without a piece must not take part, see vtkDeepShadowVolumeRepresentation).
 * A subclass moves the bytes: vtkDeepShadowMPIBrickExchange over a vtkMultiProcessController
 * in the ParaView module, an in-process store in the tests.
 */
#ifndef vtkDeepShadowBrickExchange_h
#define vtkDeepShadowBrickExchange_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkObject.h"

#include <vector> // For the gathered values

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowBrickExchange : public vtkObject
{
public:
  vtkTypeMacro(vtkDeepShadowBrickExchange, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** How many bricks take part (1: nothing is exchanged). */
  virtual int GetNumberOfBricks() = 0;
  /** This process's brick, in [0, GetNumberOfBricks()). */
  virtual int GetLocalBrick() = 0;
  /**
   * Collective: every brick's `local` (the same size on every brick), concatenated in brick
   * order into `all`. False if the exchange failed (the technique then says so and draws its
   * brick's own shadows).
   */
  virtual bool AllGather(const std::vector<float>& local, std::vector<float>& all) = 0;

  ///@{
  /** What the last frame's exchanges cost: bytes sent and received by this brick, and time. */
  vtkGetMacro(LastBytes, long long);
  vtkGetMacro(LastMilliseconds, double);
  ///@}
  /** Called by the technique around one frame's exchanges. */
  void BeginFrame();
  void Account(long long bytes, double milliseconds);

protected:
  vtkDeepShadowBrickExchange() = default;
  ~vtkDeepShadowBrickExchange() override = default;

  long long LastBytes = 0;
  double LastMilliseconds = 0.0;

private:
  vtkDeepShadowBrickExchange(const vtkDeepShadowBrickExchange&) = delete;
  void operator=(const vtkDeepShadowBrickExchange&) = delete;
};

#endif
