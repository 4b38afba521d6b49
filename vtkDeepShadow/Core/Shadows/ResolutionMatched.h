// Resolution-matched shadow maps (paper 004, Lefohn, Sengupta and Owens), CPU twin.
//
// A shadow map of MaxResolution^2 virtual texels per light face, of which only the pages the
// camera's pixels need are built. Level l of the quadtree has 2^l pages per side, each
// PageSize^2 texels; the finest level, log2(MaxResolution / PageSize), is MaxResolution
// texels wide. Per analysis pixel (every AnalysisDownsample-th pixel of the camera image) the
// first occluder along the camera's ray (the shadow map's test, OccluderTest) is the receiver
// the pixel shows; its footprint in light space (eq. 1: the area of the parallelogram of its
// texel-coordinate derivatives) picks the level whose texels are no larger than the pixel,
// and the page there is requested. Requests are deduplicated as the paper does: a pixel
// whose left and lower neighbours request the same page requests nothing (connected
// components), then sort and unique. The base level (BaseLevel(): 4 x 4 pages) is always
// built, so every lookup finds a page; when the pages do not fit the atlas, the finest level
// is coarsened until they do (section 3.3.5).
//
// Pages live in slots of an atlas of AtlasSize^2 texels. A slot holds its page and an apron
// of Apron texels of its neighbours at the same level, built like the rest, so that the
// percentage-closer filter never reads across a page border (no seams). The page table names,
// per cell of the finest level, the finest page built over it (the quadtree resolved to its
// leaves: one fetch per lookup). A lookup filters the depths of that page exactly as
// FilterShadowMap does a shadow map of its level's size.
//
// GLSL twins: Shaders/vtkDeepShadowPageRequestsCS.glsl (analysis), vtkDeepShadowLightSpaceCS.glsl
// with LIGHT_SPACE_PAGES (build) and Shaders/Shadows/ResolutionMatched.glsl (lookup).
#ifndef deepshadow_ResolutionMatched_h
#define deepshadow_ResolutionMatched_h

#include "Core/Shadows/LightSpace.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace deepshadow
{
class Camera;

/** How the virtual map is cut into pages and where they are kept. */
struct VTKDEEPSHADOWCORE_EXPORT PageLayout
{
  int PageSize = 32;
  int MaxResolution = 16384;
  int AtlasSize = 1024;
  int Apron = 1;

  /** The layout `parameters` ask for (the apron the filter reaches: 3 for Poisson, else 1). */
  static PageLayout Of(const ShadowParameters& parameters);
  int FinestLevel() const;
  /** The level always built whole (at most 2: 4 x 4 pages). */
  int BaseLevel() const;
  /** Texels per side of level `level`. */
  int LevelSize(int level) const { return this->PageSize << level; }
  int SlotSize() const { return this->PageSize + 2 * this->Apron; }
  int SlotsPerSide() const { return this->AtlasSize / this->SlotSize(); }
  /** Pages the atlas holds. */
  int Capacity() const { return this->SlotsPerSide() * this->SlotsPerSide(); }
  /** Cells (pages of the finest level) per side of the page table. */
  int TableSize() const { return 1 << this->FinestLevel(); }
  /** Base pages of `faces` faces. */
  int BasePages(int faces) const;
};

/**
 * A page request: face (slot * faces per light + face, < 32), level (< 16), page x and y at
 * that level (< 2048), packed so that sorting orders by face, level, y, then x.
 */
VTKDEEPSHADOWCORE_EXPORT std::uint32_t EncodePage(int face, int level, int x, int y);
VTKDEEPSHADOWCORE_EXPORT void DecodePage(std::uint32_t key, int& face, int& level, int& x, int& y);
/** No request (a pixel that sees no occluder, or one its neighbours already made). */
constexpr std::uint32_t NoPage = 0xffffffffu;

/**
 * Eq. 1: the level a pixel needs, from the derivatives of its finest-level texel position
 * along the image's x and y (finest texels per pixel): the coarsest whose texel is no wider
 * than sqrt(|dX x dY|), within [BaseLevel, FinestLevel].
 */
VTKDEEPSHADOWCORE_EXPORT int RequestLevel(const glm::dvec2& dX, const glm::dvec2& dY, const PageLayout& layout);

/** The page of level `level` holding finest-level texel position (x, y) (centres at integers), clamped to the face. */
VTKDEEPSHADOWCORE_EXPORT std::uint32_t PageAt(int face, int level, double x, double y, const PageLayout& layout);

/**
 * One analysis pixel's view of one light: whether its receiver lies on a face, which, and its
 * finest-level texel position there.
 */
struct AnalysisTexel
{
  bool Valid = false;
  int Face = 0;
  glm::dvec2 At{ 0.0 };
  glm::dvec3 Receiver{ 0.0 }; // world
};

/**
 * Requests of a width x height grid of analysis pixels (row by row from the lower left),
 * each pixel `downsample` image pixels wide: per pixel its page, with derivatives from its
 * neighbours on the same face (of forward and backward differences the shorter; a pixel with
 * none along an axis takes the other axis's turned a quarter, and with none at all the
 * finest level). Pixels whose left and lower neighbours request the same page get NoPage.
 * `valid` counts the pixels that requested one before that (the paper's requests).
 */
VTKDEEPSHADOWCORE_EXPORT std::vector<std::uint32_t> PageRequests(const std::vector<AnalysisTexel>& texels,
  int width, int height, int downsample, const PageLayout& layout, long long* valid = nullptr);

/** Sort and unique, without NoPage. */
VTKDEEPSHADOWCORE_EXPORT std::vector<std::uint32_t> UniquePages(std::vector<std::uint32_t> requests);

/**
 * The pages to build for the faces `faces` (their indices): the base level's and the requested ones, sorted; when
 * they exceed the atlas, requests of the finest level in use are replaced by their parents
 * until they fit. `finest` is the finest level left.
 */
VTKDEEPSHADOWCORE_EXPORT std::vector<std::uint32_t> FitPages(
  const std::vector<std::uint32_t>& unique, const std::vector<int>& faces, const PageLayout& layout, int& finest);

/** Where pages go in the atlas (AssignSlots). */
struct SlotAssignment
{
  std::vector<int> SlotOf; // per page
  std::vector<std::pair<std::uint32_t, int>> Build; // the pages to build (key, slot), in order
};

/**
 * The atlas slots of `pages` (at most `capacity`) when built pages are kept: a page in
 * `resident` (page -> slot) keeps its slot; a new one takes a free slot, then one whose page
 * is not among `pages` (evicting it). `resident` becomes exactly what the slots hold.
 */
VTKDEEPSHADOWCORE_EXPORT SlotAssignment AssignSlots(
  const std::vector<std::uint32_t>& pages, std::map<std::uint32_t, int>& resident, int capacity);

/** A page table entry: the slot of the page and its level. */
inline std::uint32_t PageTableEntry(int slot, int level)
{
  return static_cast<std::uint32_t>(slot) | (static_cast<std::uint32_t>(level) << 24);
}

/**
 * The page table of `faces` faces (TableSize()^2 cells each, row by row): per cell the entry
 * of the finest page over it among `pages`, whose slots are `slots`.
 */
VTKDEEPSHADOWCORE_EXPORT std::vector<std::uint32_t> BuildPageTable(const std::vector<std::uint32_t>& pages,
  const std::vector<int>& slots, int faces, const PageLayout& layout);

/**
 * Where a lookup at finest-level position (x, y) reads: the slot, the level and the
 * position within the slot's texels (apron included; texel centres at integers).
 */
struct PageLookup
{
  int Slot = 0;
  int Level = 0;
  double X = 0.0, Y = 0.0;
  double Scale = 1.0; // finest texels per texel of the level
};
VTKDEEPSHADOWCORE_EXPORT PageLookup LocatePage(
  const std::uint32_t* table, double x, double y, const PageLayout& layout);

/** The twin: "rmsm". Without a camera (ShadowCaster::View), the base level alone. */
class VTKDEEPSHADOWCORE_EXPORT ResolutionMatchedShadow : public LightSpaceShadow
{
public:
  ResolutionMatchedShadow(const ShadowParameters& parameters, const ShadowCaster& caster,
    const Light& light, double step, int threads);
  size_t Bytes() const override { return this->Depths.size() * sizeof(float); }

  /** The analysis's counts (one light: its faces). */
  long long GetRequested() const { return this->Requested; }
  long long GetAfterComponents() const { return this->AfterComponents; }
  int GetUnique() const { return static_cast<int>(this->Unique.size()); }
  const std::vector<std::uint32_t>& GetUniquePages() const { return this->Unique; }
  /** The pages built, sorted (base level included). */
  const std::vector<std::uint32_t>& GetPages() const { return this->Pages; }
  int GetFinestLevel() const { return this->Finest; }
  /** The receivers the analysis pixels saw on a face (world), for tests. */
  const std::vector<glm::dvec3>& GetReceivers() const { return this->Receivers; }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  void Analyse(const Camera& view, int threads);

  PageLayout Layout;
  long long Requested = 0;
  long long AfterComponents = 0;
  std::vector<std::uint32_t> Unique;
  std::vector<std::uint32_t> Pages;
  std::vector<glm::dvec3> Receivers;
  int Finest = 0;
  std::vector<std::uint32_t> Table;
  std::vector<float> Depths; // per page (in Pages' order), SlotSize^2
};

}
#endif
