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
 *   3. multiplies, per texel, the totals of the bricks that lie between it and the light into
 *      its lookups. With point-to-point messages (SendReceive) and Scan on, as a prefix
 *      product along each light's order of the bricks (deepshadow::LightOrder and
 *      ExclusiveProductScan): ceil(log2 bricks) messages of one map each, received per brick
 *      and light. Otherwise, or where the bricks have no order (overlapping boxes), by
 *      gathering every brick's totals (deepshadow::UpstreamTransmittance): bricks - 1 maps.
 * Every exchange is collective: every brick's mapper must draw every frame (ParaView's view
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

  /**
   * Whether this exchange has SendReceive (the base class has not: the bricks then gather).
   * It must answer the same on every brick.
   */
  virtual bool CanSendReceive() { return false; }
  /**
   * Point to point: sends `send` to brick `to` and receives `received.size()` values from
   * brick `from` (-1: none), sending first when `sendFirst`; `tag` tells apart a frame's
   * messages. Blocking sends and receives are enough: the scan pairs them. False if a
   * message failed.
   */
  virtual bool SendReceive(
    int to, const std::vector<float>& send, int from, std::vector<float>& received, bool sendFirst, int tag);

  ///@{
  /**
   * Whether the totals are scanned along each light (when CanSendReceive) rather than
   * gathered. On by default; off to compare (the pictures are the same).
   */
  vtkSetMacro(Scan, bool);
  vtkGetMacro(Scan, bool);
  vtkBooleanMacro(Scan, bool);
  ///@}

  ///@{
  /**
   * What the last frame's exchanges cost this brick: bytes and messages received from other
   * bricks (it sends as many bytes as it receives, summed over the bricks), the time spent in
   * them, and whether its totals were scanned (false: gathered).
   */
  vtkGetMacro(LastBytes, long long);
  vtkGetMacro(LastMessages, int);
  vtkGetMacro(LastMilliseconds, double);
  vtkGetMacro(LastScanned, bool);
  ///@}
  /** Called by the technique around one frame's exchanges. */
  void BeginFrame();
  void Account(long long bytes, int messages, double milliseconds);
  void SetLastScanned(bool scanned) { this->LastScanned = scanned; }

protected:
  vtkDeepShadowBrickExchange() = default;
  ~vtkDeepShadowBrickExchange() override = default;

  bool Scan = true;
  long long LastBytes = 0;
  int LastMessages = 0;
  double LastMilliseconds = 0.0;
  bool LastScanned = false;

private:
  vtkDeepShadowBrickExchange(const vtkDeepShadowBrickExchange&) = delete;
  void operator=(const vtkDeepShadowBrickExchange&) = delete;
};

#endif
