// Resolution-matched shadow maps, CPU side: page keys, eq. 1, requests and their
// deduplication, fitting the atlas, the page table, and the twin's lookup against a plain
// shadow map of the same level.
#include "Core/Camera.h"
#include "Core/Shadows/ResolutionMatched.h"
#include "Core/Shadows/ShadowMap.h"
#include "Core/Shadows.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <set>

using namespace deepshadow;

namespace
{
PageLayout Layout(int maxResolution = 16384, int atlas = 1024)
{
  PageLayout layout;
  layout.PageSize = 32;
  layout.MaxResolution = maxResolution;
  layout.AtlasSize = atlas;
  layout.Apron = 1;
  return layout;
}

int LevelOf(std::uint32_t key)
{
  int face, level, x, y;
  DecodePage(key, face, level, x, y);
  return level;
}

// A 33 x 33 x 17 volume over [0, 2] x [0, 2] x [0, 1]: a dense floor (z index < 2) and a
// dense ball above its middle. Opaque enough that the shadow map's threshold finds both.
struct FloorAndBall
{
  std::shared_ptr<VolumeGrid> Grid;
  TransferFunction Transfer;
  ShadowCaster Caster;
  FloorAndBall()
  {
    const glm::ivec3 dims(33, 33, 17);
    std::vector<float> values(static_cast<size_t>(dims.x) * dims.y * dims.z, 0.0f);
    for (int k = 0; k < dims.z; ++k)
      for (int j = 0; j < dims.y; ++j)
        for (int i = 0; i < dims.x; ++i)
        {
          const bool floor = k < 2;
          const bool ball = glm::length(glm::dvec3(i - 16, j - 16, k - 10)) < 4.0;
          values[i + dims.x * (j + dims.y * k)] = floor || ball ? 1.0f : 0.0f;
        }
    const glm::dmat4 indexToWorld = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 / 16));
    this->Grid = std::make_shared<VolumeGrid>(dims, values, indexToWorld);
    this->Transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 0.5, 0.0 }, { 1.0, 50.0 } });
    this->Transfer.OpacityUnitDistance = 1.0 / 16;
    this->Caster.Grid = this->Grid.get();
    this->Caster.Transfer = &this->Transfer;
  }
};

Light FromAbove()
{
  Light light;
  light.Position = { 0.3, 0.2, 1.0 };
  return light;
}

ShadowParameters Rmsm(int maxResolution)
{
  ShadowParameters p;
  p.Kind = ShadowKind::ResolutionMatched;
  p.MaxResolution = maxResolution;
  p.Filter = ShadowFilter::PCF3x3;
  return p;
}
}

TEST(ResolutionMatched, PageKeysRoundTripAndSortByFaceLevelRowColumn)
{
  int face, level, x, y;
  DecodePage(EncodePage(23, 11, 2047, 1234), face, level, x, y);
  EXPECT_EQ(face, 23);
  EXPECT_EQ(level, 11);
  EXPECT_EQ(x, 2047);
  EXPECT_EQ(y, 1234);
  EXPECT_LT(EncodePage(0, 9, 2047, 2047), EncodePage(1, 2, 0, 0));
  EXPECT_LT(EncodePage(0, 2, 2047, 2047), EncodePage(0, 3, 0, 0));
  EXPECT_LT(EncodePage(0, 3, 2047, 4), EncodePage(0, 3, 0, 5));
  EXPECT_NE(EncodePage(31, 15, 2047, 2047), NoPage);
}

TEST(ResolutionMatched, LevelMatchesTheParallelogramOfEquationOne)
{
  const PageLayout layout = Layout(); // finest level 9, base 2
  ASSERT_EQ(layout.FinestLevel(), 9);
  ASSERT_EQ(layout.BaseLevel(), 2);
  EXPECT_EQ(RequestLevel({ 1, 0 }, { 0, 1 }, layout), 9);
  EXPECT_EQ(RequestLevel({ 0.3, 0 }, { 0, 0.3 }, layout), 9);
  EXPECT_EQ(RequestLevel({ 2, 0 }, { 0, 2 }, layout), 8);
  EXPECT_EQ(RequestLevel({ 3.9, 0 }, { 0, 3.9 }, layout), 8);
  EXPECT_EQ(RequestLevel({ 5, 0 }, { 0, 5 }, layout), 7);
  EXPECT_EQ(RequestLevel({ 1e6, 0 }, { 0, 1e6 }, layout), 2);
  // Anisotropic: 8 x 0.5 has the area of 2 x 2 (the bounding square would say 8).
  EXPECT_EQ(RequestLevel({ 8, 0 }, { 0, 0.5 }, layout), 8);
  // Rotated: the same area.
  EXPECT_EQ(RequestLevel({ 2, 2 }, { -2, 2 }, layout), 8);
  // Degenerate (parallel derivatives): no area, the finest level.
  EXPECT_EQ(RequestLevel({ 4, 0 }, { 8, 0 }, layout), 9);
}

TEST(ResolutionMatched, RequestsFollowTheFootprintAndComponentsDropRepeats)
{
  // A ground seen in perspective: row j's texels are 0.5 * 1.25^j finest texels wide.
  const PageLayout layout = Layout();
  const int width = 64, height = 40;
  std::vector<AnalysisTexel> texels(static_cast<size_t>(width) * height);
  double y = 100.0;
  for (int j = 0; j < height; ++j)
  {
    const double scale = 0.5 * std::pow(1.25, j);
    for (int i = 0; i < width; ++i)
    {
      AnalysisTexel& t = texels[static_cast<size_t>(j) * width + i];
      t.Valid = true;
      t.At = glm::dvec2(1000.0 + scale * i, y);
    }
    y += scale;
  }
  long long valid = 0;
  const std::vector<std::uint32_t> requests = PageRequests(texels, width, height, 1, layout, &valid);
  EXPECT_EQ(valid, static_cast<long long>(width) * height);
  const long long kept = std::count_if(requests.begin(), requests.end(), [](std::uint32_t r) { return r != NoPage; });
  const std::vector<std::uint32_t> unique = UniquePages(requests);
  // Neighbours mostly ask for the same page: connected components keep few requests.
  EXPECT_LT(kept, valid / 10);
  EXPECT_LE(static_cast<long long>(unique.size()), kept);
  // Every page some pixel needs survives: compare with the pages without deduplication.
  std::set<std::uint32_t> all;
  for (int j = 0; j < height; ++j)
  {
    const double scale = 0.5 * std::pow(1.25, j);
    for (int i = 0; i < width; ++i)
    {
      const AnalysisTexel& t = texels[static_cast<size_t>(j) * width + i];
      // Along x both differences are equal; along y the backward one (to the nearer row) is
      // the shorter, except on the first row, which has only the forward one.
      const double dy = j > 0 ? 0.5 * std::pow(1.25, j - 1) : scale;
      const int level = RequestLevel({ scale, 0.0 }, { 0.0, dy }, layout);
      all.insert(PageAt(0, level, t.At.x, t.At.y, layout));
    }
  }
  EXPECT_EQ(std::vector<std::uint32_t>(all.begin(), all.end()), unique);
  // Near rows (small texels) ask for the finest level, far rows for coarser ones.
  EXPECT_EQ(LevelOf(requests[0]), 9);
  std::set<int> levels;
  for (const std::uint32_t key : unique)
  {
    levels.insert(LevelOf(key));
  }
  EXPECT_GE(levels.size(), 5u);
  // With every second pixel analysed (downsample 2), each spans twice the texels: one level coarser.
  std::vector<AnalysisTexel> half;
  for (int j = 0; j < height; j += 2)
    for (int i = 0; i < width; i += 2)
      half.push_back(texels[static_cast<size_t>(j) * width + i]);
  const std::vector<std::uint32_t> coarse = PageRequests(half, width / 2, height / 2, 2, layout);
  EXPECT_EQ(LevelOf(coarse[0]), 9); // 1 finest texel per image pixel still
}

TEST(ResolutionMatched, FittingTheAtlasCoarsensTheFinestLevelAndKeepsTheBase)
{
  const PageLayout roomy = Layout(16384, 1024);     // 30^2 = 900 slots
  const PageLayout tight = Layout(16384, 34 * 12);  // 144 slots
  std::vector<std::uint32_t> requested;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 20; ++x)
      requested.push_back(EncodePage(0, 9, 100 + x, 200 + y));
  requested = UniquePages(requested);
  int finest = 0;
  const std::vector<std::uint32_t> all = FitPages(requested, { 0 }, roomy, finest);
  EXPECT_EQ(finest, 9);
  EXPECT_EQ(all.size(), requested.size() + 16);
  const std::vector<std::uint32_t> fitted = FitPages(requested, { 0 }, tight, finest);
  EXPECT_EQ(finest, 8);
  EXPECT_LE(static_cast<int>(fitted.size()), tight.Capacity());
  EXPECT_EQ(fitted.size(), 10u * 6u + 16u); // 20 x 12 pages become 10 x 6 parents
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      EXPECT_TRUE(std::binary_search(fitted.begin(), fitted.end(), EncodePage(0, 2, x, y)));
  // Two faces: the base of both.
  EXPECT_EQ(FitPages({}, { 0, 6 }, roomy, finest).size(), 32u);
}

TEST(ResolutionMatched, KeptPagesKeepTheirSlotsAndNewOnesEvictOnlyWhenFull)
{
  std::map<std::uint32_t, int> resident;
  const std::vector<std::uint32_t> first{ 10, 20, 30 };
  SlotAssignment a = AssignSlots(first, resident, 4);
  EXPECT_EQ(a.SlotOf, (std::vector<int>{ 0, 1, 2 }));
  EXPECT_EQ(a.Build.size(), 3u);
  // The view moves: 20 and 30 stay where they are, 40 takes the free slot, nothing is built again.
  a = AssignSlots({ 20, 30, 40 }, resident, 4);
  EXPECT_EQ(a.SlotOf, (std::vector<int>{ 1, 2, 3 }));
  ASSERT_EQ(a.Build.size(), 1u);
  EXPECT_EQ(a.Build[0], std::make_pair(std::uint32_t(40), 3));
  EXPECT_EQ(resident.size(), 4u); // 10 is kept while there is room
  // Full: 50 and 60 take the slots of 10 and 20, which this view does not need.
  a = AssignSlots({ 30, 40, 50, 60 }, resident, 4);
  EXPECT_EQ(a.SlotOf, (std::vector<int>{ 2, 3, 0, 1 }));
  EXPECT_EQ(a.Build.size(), 2u);
  EXPECT_EQ(resident, (std::map<std::uint32_t, int>{ { 30, 2 }, { 40, 3 }, { 50, 0 }, { 60, 1 } }));
  // The view comes back: 10 and 20 are built again.
  a = AssignSlots({ 10, 20, 30 }, resident, 4);
  EXPECT_EQ(a.Build.size(), 2u);
  EXPECT_EQ(resident.size(), 4u);
  for (size_t i = 0; i < 3; ++i)
  {
    EXPECT_EQ(resident.at(std::vector<std::uint32_t>{ 10, 20, 30 }[i]), a.SlotOf[i]);
  }
}

TEST(ResolutionMatched, PageTableNamesTheFinestPageOverEachCell)
{
  const PageLayout layout = Layout(1024); // finest 5: 32 x 32 cells
  std::vector<std::uint32_t> pages;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      pages.push_back(EncodePage(0, 2, x, y));
  pages.push_back(EncodePage(0, 5, 9, 17)); // a finest page
  pages.push_back(EncodePage(0, 3, 2, 4));  // a level-3 page over cells (8..11, 16..19)
  pages = UniquePages(pages);
  std::vector<int> slots(pages.size());
  for (size_t i = 0; i < slots.size(); ++i)
    slots[i] = static_cast<int>(100 + i);
  const std::vector<std::uint32_t> table = BuildPageTable(pages, slots, 1, layout);
  auto slotOf = [&](std::uint32_t key) {
    return 100 + static_cast<int>(std::lower_bound(pages.begin(), pages.end(), key) - pages.begin());
  };
  auto entryAt = [&](int cx, int cy) { return table[static_cast<size_t>(cy) * 32 + cx]; };
  EXPECT_EQ(entryAt(9, 17), PageTableEntry(slotOf(EncodePage(0, 5, 9, 17)), 5));
  EXPECT_EQ(entryAt(8, 17), PageTableEntry(slotOf(EncodePage(0, 3, 2, 4)), 3));
  EXPECT_EQ(entryAt(11, 19), PageTableEntry(slotOf(EncodePage(0, 3, 2, 4)), 3));
  EXPECT_EQ(entryAt(12, 19), PageTableEntry(slotOf(EncodePage(0, 2, 1, 2)), 2));
  EXPECT_EQ(entryAt(0, 0), PageTableEntry(slotOf(EncodePage(0, 2, 0, 0)), 2));
  // The lookup at finest texel (9 * 32 + 5, 17 * 32 + 7) reads texel (5, 7) of that page,
  // past its apron of 1.
  const PageLookup fine = LocatePage(table.data(), 9 * 32 + 5, 17 * 32 + 7, layout);
  EXPECT_EQ(fine.Slot, slotOf(EncodePage(0, 5, 9, 17)));
  EXPECT_DOUBLE_EQ(fine.X, 6.0);
  EXPECT_DOUBLE_EQ(fine.Y, 8.0);
  EXPECT_DOUBLE_EQ(fine.Scale, 1.0);
  // In the level-3 page: its texel is 4 finest texels wide.
  const PageLookup coarse = LocatePage(table.data(), 8 * 32 + 1.5, 16 * 32 + 5.5, layout);
  EXPECT_EQ(coarse.Level, 3);
  EXPECT_DOUBLE_EQ(coarse.Scale, 4.0);
  EXPECT_DOUBLE_EQ(coarse.X, (8 * 32 + 2.0) / 4.0 - 0.5 - 2 * 32 + 1);
}

TEST(ResolutionMatched, BaseLevelAloneIsTheShadowMapOfItsSize)
{
  // Without a camera only the base level (4 x 4 pages of 32^2: a 128^2 map) is built; away
  // from the map's edge (where the apron holds rays beyond it and the map clamps), every
  // lookup must equal the 128^2 shadow map's, across page borders too.
  const FloorAndBall scene;
  const Light light = FromAbove();
  const double step = 1.0 / 32;
  ShadowParameters rmsm = Rmsm(1024);
  ShadowParameters map = rmsm;
  map.Kind = ShadowKind::ShadowMap;
  map.MapSize = 128;
  for (const ShadowFilter filter : { ShadowFilter::None, ShadowFilter::PCF2x2, ShadowFilter::PCF3x3, ShadowFilter::Poisson })
  {
    rmsm.Filter = map.Filter = filter;
    const auto pages = MakeLightShadow(rmsm, scene.Caster, light, step / 1.0, 2);
    const auto plain = MakeLightShadow(map, scene.Caster, light, step / 1.0, 2);
    const auto* twin = dynamic_cast<const ResolutionMatchedShadow*>(pages.get());
    ASSERT_NE(twin, nullptr);
    EXPECT_EQ(twin->GetPages().size(), 16u);
    int shadowed = 0, compared = 0;
    for (int n = 0; n < 4000; ++n)
    {
      const glm::dvec3 p(0.4 + 1.2 * std::fmod(n * 0.618034, 1.0), 0.4 + 1.2 * std::fmod(n * 0.414214, 1.0), 0.07 + 0.3 * std::fmod(n * 0.7548, 1.0));
      const double a = pages->Visibility(p).r, b = plain->Visibility(p).r;
      ASSERT_EQ(a, b) << "at " << p.x << " " << p.y << " " << p.z;
      shadowed += a < 0.5 ? 1 : 0;
      ++compared;
    }
    // The points see the ball's shadow and the lit floor both.
    EXPECT_GT(shadowed, compared / 50);
    EXPECT_LT(shadowed, compared - compared / 50);
  }
}

TEST(ResolutionMatched, TheCameraAsksForFinePagesNearItAndSharpensTheShadow)
{
  // The camera close to the ball's shadow on the floor: the twin requests pages of several
  // levels, and at the receivers it sees it follows exact opaque visibility (opaque rays)
  // far closer than a 512^2 shadow map does.
  const FloorAndBall scene;
  const Light light = FromAbove();
  const double step = 1.0 / 32;
  ShadowParameters exact;
  exact.Kind = ShadowKind::Rays;
  exact.Opaque = true;
  const auto truth = MakeLightShadow(exact, scene.Caster, light, step, 2);
  // Where the shadow's edge crosses y = 0.75 on the floor.
  double edge = 0.0;
  for (double x = 1.4; x > 0.6; x -= 0.002)
  {
    if (truth->Visibility({ x, 0.75, 0.1 }).r < 0.5)
    {
      edge = x;
      break;
    }
  }
  ASSERT_GT(edge, 0.0);
  const glm::dmat4 view = glm::lookAt(glm::dvec3(edge, 0.6, 0.2), glm::dvec3(edge, 0.75, 0.1), glm::dvec3(0, 0, 1));
  const glm::dmat4 projection = glm::perspective(glm::radians(30.0), 1.0, 0.01, 10.0);
  const Camera camera(projection * view, 64, 64);
  ShadowCaster caster = scene.Caster;
  caster.View = &camera;
  ShadowParameters p = Rmsm(8192);
  p.AnalysisDownsample = 1;
  const auto shadow = MakeLightShadow(p, caster, light, step, 2);
  const auto* twin = dynamic_cast<const ResolutionMatchedShadow*>(shadow.get());
  ASSERT_NE(twin, nullptr);
  EXPECT_GT(twin->GetRequested(), 64 * 64 / 2);
  EXPECT_LT(twin->GetAfterComponents(), twin->GetRequested() / 4);
  EXPECT_GT(twin->GetUnique(), 4);
  std::set<int> levels;
  for (const std::uint32_t key : twin->GetUniquePages())
  {
    levels.insert(LevelOf(key));
  }
  EXPECT_GE(levels.size(), 2u);
  EXPECT_EQ(twin->GetFinestLevel(), 8);

  ShadowParameters coarse = p;
  coarse.Kind = ShadowKind::ShadowMap;
  coarse.MapSize = 512;
  const auto blocky = MakeLightShadow(coarse, scene.Caster, light, step, 2);
  // Exact visibility from the receiver moved towards the light by the maps' bias (2 steps):
  // receivers lie just inside the floor, which would shadow them.
  const glm::dvec3 toLight = glm::normalize(light.Position);
  double rmsmError = 0.0, mapError = 0.0;
  for (const glm::dvec3& receiver : twin->GetReceivers())
  {
    const double exactVisibility = truth->Visibility(receiver + 2.0 * step * toLight).r;
    rmsmError += std::abs(shadow->Visibility(receiver).r - exactVisibility);
    mapError += std::abs(blocky->Visibility(receiver).r - exactVisibility);
  }
  EXPECT_GT(mapError, 20.0);
  EXPECT_LT(rmsmError, 0.5 * mapError) << "RMSM " << rmsmError << ", 512^2 map " << mapError;
}
