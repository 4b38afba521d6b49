// Internal: the chunked node memory of deep shadow maps on the GPU (Core/Shadows/NodeChunks.h
// is its twin and says why chunks). One buffer holds a region of chunks per shadowed light
// (slot); a chunk is its link and then its nodes, one RG32F (grey) or RGBA32F (coloured)
// entry each. The build writes it as a shader storage buffer (binding 3) and takes chunks
// with an atomic counter per slot; the lookup reads it as a buffer texture (u_shadowNodes).
//
// A light may use at most its limit (ChunkPoolCapacity, as the twin), but the regions start
// smaller, whatever the limit, and grow to what a build asked for: a sparse scene then holds
// the memory its nodes need, not its limit. Growing moves every region, so every light's map
// is built again.
#ifndef vtkDeepShadowNodePool_h
#define vtkDeepShadowNodePool_h

#include <string>
#include <vector>

class vtkOpenGLRenderWindow;

namespace deepshadow
{
class UniformSink;

class NodePool
{
public:
  /**
   * Room for one region per entry of `limits` (each light's limit, in chunks) of chunks of
   * `chunkNodes` nodes. The GL may allow less than the limits (chunk numbers, stored as
   * floats, stay below MaxPoolChunks in all; a buffer texture has GL_MAX_TEXTURE_BUFFER_SIZE entries):
   * `problem` then says so and the limits are lowered. `remade` when the buffer was (re)made:
   * every map must be built again. False, with `problem` set, when the GL refused it. A new
   * buffer's regions start at `start` chunks (at most the limits): builds grow them.
   */
  bool Reserve(vtkOpenGLRenderWindow* window, std::vector<long long> limits, long long start, int chunkNodes,
    bool colored, bool& remade, std::string& problem);

  /** Where slot `slot`'s chunks start, and how many it may take in this build. */
  long long Base(int slot) const;
  long long Capacity(int slot) const;
  long long Limit(int slot) const { return this->Limits[static_cast<size_t>(slot)]; }

  /**
   * After a build in which slot asked for `requested` chunks: grows the regions when its limit
   * allows more than they hold. True when it grew (every map must be built again).
   */
  bool Grow(long long requested, int slot, std::string& problem);

  void BindBuild() const;
  void UnbindBuild() const;
  void BindLookup(UniformSink& sink, vtkOpenGLRenderWindow* window);
  void UnbindLookup();

  long long ChunkBytes() const;
  long long AllocatedBytes() const;
  void Release();

private:
  bool Allocate(std::string& problem);

  vtkOpenGLRenderWindow* Window = nullptr;
  unsigned int Buffer = 0;
  unsigned int Texture = 0;
  int Unit = -1;
  int Nodes = 0;
  bool Colored = false;
  long long Region = 0; // chunks per slot
  std::vector<long long> Limits;
};
}
#endif
