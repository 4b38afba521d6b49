// Internal: the GPU half of the resolution-matched maps' analysis (paper 004, section 3.3.2;
// vtkDeepShadowResolutionMatchedTechnique): the receiver each analysis pixel shows, the page
// it needs, and their deduplication (connected components with compaction, bitonic sort,
// unique). The CPU twin is deepshadow::PageRequests and UniquePages
// (Core/Shadows/ResolutionMatched.h).
#ifndef vtkDeepShadowPageAnalysis_h
#define vtkDeepShadowPageAnalysis_h

#include "GL/ComputeProgram.h"
#include "LightSpaceFaces.h"

#include "Core/Shadows/ResolutionMatched.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <string>
#include <vector>

class vtkDeepShadowTechnique;

namespace deepshadow
{
struct ShadowContext;

class PageAnalysis
{
public:
  /** What the last analysis counted. */
  struct Counts
  {
    long long Requested = 0;       // pixels (per light) whose receiver lies on a face
    long long AfterComponents = 0; // requests left by the connected components
  };

  /**
   * The pages, sorted and unique, that every `downsample`-th pixel of the context's camera
   * needs on the lights' faces (face index slot * facesPerLight + face). The receiver march
   * is a build pass of `technique` (its features, feeler table and build time). False, and
   * `error`, if a program did not compile.
   */
  bool Analyse(vtkDeepShadowTechnique* technique, const ShadowContext& context, const SlotFaces& faces,
    int facesPerLight, const PageLayout& layout, int downsample, std::vector<std::uint32_t>& unique,
    std::string& error);
  const Counts& GetCounts() const { return this->Last; }
  void Release();

private:
  /** Step 1: each analysis pixel's first occluder along its ray into Hits. */
  bool FindReceivers(vtkDeepShadowTechnique* technique, const ShadowContext& context, int downsample,
    std::string& error);
  /** The four stages of vtkDeepShadowPageRequestsCS, composed for the lights' faces. */
  bool BuildStages(const SlotFaces& faces, std::string& error);
  /** Step 2: one request per pixel and face (stage 0), the connected components' survivors
   * listed (stage 1); returns how many were listed. */
  unsigned int ListRequests(const ShadowContext& context, const SlotFaces& faces, int facesPerLight,
    const PageLayout& layout, int downsample);
  /** Step 3: the listed requests sorted (stage 2) and made unique (stage 3), read back;
   * returns the requests stage 0 counted. */
  long long SortUnique(unsigned int listed, std::vector<std::uint32_t>& unique);

  glm::ivec2 AnalysisSize(const ShadowContext& context, int downsample) const;

  unsigned int Hits = 0; // the analysis pixels' first-occluder distances, R32F
  glm::ivec2 HitsSize{ 0 };
  unsigned int Requests = 0, List = 0, Unique = 0;
  long long RequestsBytes = 0, ListBytes = 0, UniqueBytes = 0;
  ComputeProgram Receivers;
  ComputeProgram Stages[4];
  Counts Last;
};
}

#endif
