// The module's side of a shadow technique (not installed): the hooks a technique implements
// with the module's internal types, what the mappers and the pass call, and the helpers
// techniques build with. The installed vtkDeepShadow*Technique.h name none of these types,
// so a technique written outside the tree builds against this header set instead.
#ifndef vtkDeepShadowTechniqueInternals_h
#define vtkDeepShadowTechniqueInternals_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowTechnique.h"

#include "GL/ComputeProgram.h"
#include "Core/Shadows/ShadowGrid.h"
#include "ShadowSlots.h"
#include "Volume/TransferTableTexture.h"

#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include <glm/vec3.hpp>

#include <array>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace deepshadow
{
struct ShadowContext;
class UniformSink;
}

/**
 * What a technique provides that takes internal types. Each concrete technique derives its
 * own (a nested class, which may reach its members) and installs it with
 * Internals::SetHooks in its constructor.
 */
class vtkDeepShadowTechnique::Hooks
{
public:
  virtual ~Hooks() = default;
  /** (Re)allocates its storage for `slots`; calls slots.Invalidate() when it did. */
  virtual bool AllocateStructures(deepshadow::ShadowContext&, deepshadow::ShadowSlots&)
  {
    return true;
  }
  /** Builds the structures of the given slots. */
  virtual bool BuildStructures(
    deepshadow::ShadowContext&, const deepshadow::ShadowSlots&, const std::vector<int>&)
  {
    return true;
  }
  /**
   * Every frame, after the builds: the structures that follow the camera (the
   * resolution-matched maps' pages). Adds the slots it built anything for to `rebuilt`, and
   * to `cacheKey` whatever the lookup now depends on.
   */
  virtual bool FollowView(deepshadow::ShadowContext&, const deepshadow::ShadowSlots&,
    std::set<int>& /*rebuilt*/, std::vector<double>& /*cacheKey*/)
  {
    return true;
  }
  /**
   * After the builds of a frame, whether or not a slot was rebuilt (`rebuilt`): what the
   * structures take from outside the process (vtkDeepShadowBrickExchange). Appends to
   * `cacheKey` whatever the lookup now depends on.
   */
  virtual bool ExchangeStructures(deepshadow::ShadowContext&, const deepshadow::ShadowSlots&,
    const std::set<int>& /*rebuilt*/, std::vector<double>& /*cacheKey*/)
  {
    return true;
  }
  /** Binds what the lookup reads and sets its uniforms (ray caster or cache pass). */
  virtual void BindLookup(deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context) = 0;
};

/** The light-space techniques' further hooks (layers, build and lookup uniforms). */
class vtkDeepShadowLightSpaceTechnique::Hooks : public vtkDeepShadowTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowLightSpaceTechnique& self)
    : Self(&self)
  {
  }
  /** Layers per face (deep shadow map nodes, stochastic photons, opacity levels' mesh steps). */
  virtual int GetLayersPerFace(const deepshadow::ShadowContext&) const { return 1; }
  virtual void SetBuildUniforms(deepshadow::UniformSink&, const deepshadow::ShadowContext&) {}
  /** Before the dispatches of slot `slot`'s faces. */
  virtual void SetSlotBuildUniforms(deepshadow::UniformSink&, int /*slot*/) {}
  /**
   * After a build of the slots `built` (of `slotCount`), read back by EndMapBuild: keeps what
   * the build found, and returns the slots to build again (the deep shadow map's node pool
   * ran out); none by default. Should GetLayersPerFace() now say otherwise, the maps are laid
   * out again and every slot is built.
   */
  virtual std::vector<int> AfterBuild(const std::vector<int>& /*built*/, int /*slotCount*/) { return {}; }
  /** (Re)allocates the maps' texture for their current shape; false (and LastError) if it cannot. */
  bool AllocateMapTexture(const deepshadow::ShadowContext& context);
  virtual void SetMapLookupUniforms(deepshadow::UniformSink&, const deepshadow::ShadowContext&) {}

  bool AllocateStructures(deepshadow::ShadowContext& context, deepshadow::ShadowSlots& slots) override;
  bool BuildStructures(deepshadow::ShadowContext& context, const deepshadow::ShadowSlots& slots,
    const std::vector<int>& stale) override;
  bool ExchangeStructures(deepshadow::ShadowContext& context, const deepshadow::ShadowSlots& slots,
    const std::set<int>& rebuilt, std::vector<double>& cacheKey) override;
  void BindLookup(deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context) override;

private:
  vtkDeepShadowLightSpaceTechnique* Self;
};

/** A technique's GPU state, and the calls that take internal types. */
class vtkDeepShadowTechnique::Internals
{
public:
  // ---- Used by the mappers and the pass ----

  /** Brings the shadow structures up to date; false (and GetLastError()) on failure. */
  static bool Prepare(vtkDeepShadowTechnique* self, deepshadow::ShadowContext& context);
  /** The lights given a shadow structure by the last Prepare() (u_shadowSlotCount). */
  static int SlotCount(const vtkDeepShadowTechnique* self);
  /** Sets the lookup's uniforms and binds its textures on the ray caster's program. */
  static void Bind(vtkDeepShadowTechnique* self, deepshadow::UniformSink& sink,
    const deepshadow::ShadowContext& context, bool direct = false);
  /**
   * Used by deepshadow::OtherVolumeShadows: evaluates this technique's own lookup (never its
   * cache, which covers its volume's box only) at every node of `frame`, for each light it
   * has a structure for, and multiplies the answer into slab l of `grid` (RGBA16F) for the
   * context's light l; slabs not in the bit mask `writtenSlabs` are stored instead. Returns
   * the mask with its slabs added, or -1 (and GetLastError()) if the pass failed. Prepare()
   * must have run this frame.
   */
  static int EvaluateOnGrid(vtkDeepShadowTechnique* self, const deepshadow::ShadowContext& context,
    vtkTextureObject* grid, const deepshadow::GridFrame& frame, int writtenSlabs);

  // ---- Used by techniques ----

  /** Installs the technique's hooks (its constructor does). */
  static void SetHooks(vtkDeepShadowTechnique* self, std::unique_ptr<Hooks> hooks);
  /** World step of feelers and light rays for the current context. */
  static double FeelerStep(const vtkDeepShadowTechnique* self, const deepshadow::ShadowContext& context);
  /** The Feeler feature's uniforms (its table must be active). */
  static void SetFeelerUniforms(const vtkDeepShadowTechnique* self, deepshadow::UniformSink& sink,
    const deepshadow::ShadowContext& context);
  /**
   * Starts a build pass: composes `shaderTemplate` with the volume-sampling, empty-space and
   * feeler features (and `runtime` ones), compiles it into `program` if needed, binds the
   * volume, block map and feeler table and sets their uniforms. False (and LastError) if it
   * does not compile.
   */
  static bool BeginBuildPass(vtkDeepShadowTechnique* self, deepshadow::ComputeProgram& program,
    const std::string& shaderTemplate, const deepshadow::ShadowContext& context,
    const std::string& runtimeName = std::string(), const std::string& runtimeSource = std::string());
  /** Ends it: waits for the GL, unbinds, and adds the pass to the build time. */
  static void EndBuildPass(vtkDeepShadowTechnique* self, const deepshadow::ShadowContext& context);

  std::unique_ptr<Hooks> TechniqueHooks;
  // The feeler's table: the casting transfer function, opacity corrected for the feeler step
  // (the same holder as the ray caster's table).
  deepshadow::TransferTableTexture FeelerTable;
  // Components 1.. of a volume of several (their functions over their ranges, the same step).
  std::array<deepshadow::TransferTableTexture, 3> ComponentFeelerTables;
  int ComponentFeelerCount = 0; // how many of them are in use
  // Zero-opacity blocks of the volume's opacity may be skipped (not with a shadow property).
  bool SkipEmpty = true;
  deepshadow::ShadowSlots Slots;
  // Shadow-casting lights left without a slot at the last warning (said once while it lasts).
  int DroppedSaid = 0;
  // How many times coarser the structures are built (ShadowContext::RebuildCoarsening).
  int Coarsening = 1;
  // Build timing of the current Prepare.
  double PassStart = 0.0;
  double PassMilliseconds = 0.0;
  int Passes = 0;

  // The cache ("PP"): one slab of a 3D texture per shadow-casting light.
  vtkSmartPointer<vtkTextureObject> Cache;
  deepshadow::GridFrame CacheFrame;
  glm::ivec3 CacheDims{ 0 };
  int CacheSlabs = 0;
  bool CacheColored = false;
  deepshadow::ShadowSlots CacheSlots;
  deepshadow::ComputeProgram CacheBuild;
  // The lookup evaluated on other volumes' grids (deepshadow::OtherVolumeShadows).
  deepshadow::ComputeProgram OtherBuild;

  void ReleaseCache(vtkWindow* window)
  {
    if (this->Cache)
    {
      this->Cache->ReleaseGraphicsResources(window);
      this->Cache = nullptr;
    }
    this->CacheBuild.Release();
    this->CacheSlots.Invalidate();
  }

private:
  /** The feeler's table (the casting transfer function for the feeler step), if stale. */
  static void UpdateFeelerTable(
    vtkDeepShadowTechnique* self, const deepshadow::ShadowContext& context, bool colored);
  /**
   * The grid pass (vtkDeepShadowCachedShadowCS): the lookup at every node of `frame` into
   * `grid` (RGBA16F if `colored`, else R16F), per (slot, slab). `storeMask` < 0: store (a
   * cache, which may skip empty nodes); else multiply into what is stored, except in the
   * slabs whose bit is set, which are stored.
   */
  static bool RunGridPass(vtkDeepShadowTechnique* self, deepshadow::ComputeProgram& program,
    const std::string& defines, const deepshadow::ShadowContext& context, vtkTextureObject* grid,
    bool colored, const deepshadow::GridFrame& frame,
    const std::vector<std::pair<int, int>>& slotsAndSlabs, const deepshadow::ShadowSlots& slots,
    bool skipEmpty, const glm::vec3& reach, int storeMask);
  /** Brings the cache of every slot whose `key` (structure, lookup, cache) changed up to date. */
  static bool PrepareCache(vtkDeepShadowTechnique* self, deepshadow::ShadowContext& context,
    std::vector<double> key, const std::vector<double>& drawnOpacityKey, std::set<int>& rebuilt);
};

#endif
