#include "Core/Shadows/ResolutionMatched.h"

#include "Core/Camera.h"
#include "Core/Parallel.h"
#include "Core/Shadows/ShadowMap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace deepshadow
{

PageLayout PageLayout::Of(const ShadowParameters& parameters)
{
  PageLayout layout;
  layout.PageSize = parameters.PageSize;
  layout.MaxResolution = parameters.MaxResolution;
  layout.AtlasSize = parameters.AtlasSize;
  // The filter's farthest tap from the nearest texel: the Poisson disc's radius 2, rounded.
  layout.Apron = parameters.Filter == ShadowFilter::Poisson ? 3 : 1;
  return layout;
}

int PageLayout::FinestLevel() const
{
  int level = 0;
  while ((this->PageSize << (level + 1)) <= this->MaxResolution)
  {
    ++level;
  }
  return level;
}

int PageLayout::BaseLevel() const
{
  return std::min(2, this->FinestLevel());
}

int PageLayout::BasePages(int faces) const
{
  const int side = 1 << this->BaseLevel();
  return faces * side * side;
}

std::uint32_t EncodePage(int face, int level, int x, int y)
{
  return (static_cast<std::uint32_t>(face) << 26) | (static_cast<std::uint32_t>(level) << 22) |
    (static_cast<std::uint32_t>(y) << 11) | static_cast<std::uint32_t>(x);
}

void DecodePage(std::uint32_t key, int& face, int& level, int& x, int& y)
{
  face = static_cast<int>(key >> 26);
  level = static_cast<int>((key >> 22) & 15u);
  y = static_cast<int>((key >> 11) & 2047u);
  x = static_cast<int>(key & 2047u);
}

int RequestLevel(const glm::dvec2& dX, const glm::dvec2& dY, const PageLayout& layout)
{
  const int finest = layout.FinestLevel();
  const double side = std::sqrt(std::abs(dX.x * dY.y - dX.y * dY.x));
  if (!(side >= 1.0))
  {
    return finest; // a pixel smaller than a finest texel (or no footprint at all)
  }
  const int coarser = static_cast<int>(std::floor(std::log2(std::min(side, 1e9))));
  return std::clamp(finest - coarser, layout.BaseLevel(), finest);
}

std::uint32_t PageAt(int face, int level, double x, double y, const PageLayout& layout)
{
  // A page of level l spans PageSize * 2^(finest - l) finest texels.
  const double span = static_cast<double>(layout.PageSize) * std::ldexp(1.0, layout.FinestLevel() - level);
  const int last = (1 << level) - 1;
  auto page = [&](double position) {
    const double p = std::floor((ClampTexelPosition(position, layout.MaxResolution) + 0.5) / span);
    return std::clamp(static_cast<int>(p), 0, last);
  };
  return EncodePage(face, level, page(x), page(y));
}

std::vector<std::uint32_t> PageRequests(const std::vector<AnalysisTexel>& texels, int width, int height,
  int downsample, const PageLayout& layout, long long* valid)
{
  auto at = [&](int i, int j) -> const AnalysisTexel* {
    if (i < 0 || j < 0 || i >= width || j >= height)
    {
      return nullptr;
    }
    const AnalysisTexel& t = texels[static_cast<size_t>(j) * width + i];
    return t.Valid ? &t : nullptr;
  };
  // Of the forward and backward differences along (di, dj) on the same face, the shorter.
  auto derivative = [&](const AnalysisTexel& centre, int i, int j, int di, int dj, glm::dvec2& d) {
    bool found = false;
    for (const int s : { 1, -1 })
    {
      const AnalysisTexel* n = at(i + s * di, j + s * dj);
      if (n && n->Face == centre.Face)
      {
        const glm::dvec2 candidate = double(s) * (n->At - centre.At);
        if (!found || glm::dot(candidate, candidate) < glm::dot(d, d))
        {
          d = candidate;
          found = true;
        }
      }
    }
    return found;
  };
  std::vector<std::uint32_t> pages(texels.size(), NoPage);
  long long count = 0;
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const AnalysisTexel* t = at(i, j);
      if (!t)
      {
        continue;
      }
      glm::dvec2 dX(0.0), dY(0.0);
      const bool hasX = derivative(*t, i, j, 1, 0, dX);
      const bool hasY = derivative(*t, i, j, 0, 1, dY);
      int level = layout.FinestLevel();
      if (hasX || hasY)
      {
        // One axis alone: a square footprint, the other side turned a quarter.
        dX = hasX ? dX : glm::dvec2(dY.y, -dY.x);
        dY = hasY ? dY : glm::dvec2(-dX.y, dX.x);
        level = RequestLevel(dX / double(downsample), dY / double(downsample), layout);
      }
      pages[static_cast<size_t>(j) * width + i] = PageAt(t->Face, level, t->At.x, t->At.y, layout);
      ++count;
    }
  }
  if (valid)
  {
    *valid = count;
  }
  // Connected components: a request its left and lower neighbours make too is theirs.
  std::vector<std::uint32_t> kept(pages.size(), NoPage);
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const size_t k = static_cast<size_t>(j) * width + i;
      const std::uint32_t left = i > 0 ? pages[k - 1] : NoPage;
      const std::uint32_t below = j > 0 ? pages[k - static_cast<size_t>(width)] : NoPage;
      if (pages[k] != NoPage && pages[k] != left && pages[k] != below)
      {
        kept[k] = pages[k];
      }
    }
  }
  return kept;
}

std::vector<std::uint32_t> UniquePages(std::vector<std::uint32_t> requests)
{
  requests.erase(std::remove(requests.begin(), requests.end(), NoPage), requests.end());
  std::sort(requests.begin(), requests.end());
  requests.erase(std::unique(requests.begin(), requests.end()), requests.end());
  return requests;
}

std::vector<std::uint32_t> FitPages(
  const std::vector<std::uint32_t>& unique, const std::vector<int>& faces, const PageLayout& layout, int& finest)
{
  const int base = layout.BaseLevel();
  std::vector<std::uint32_t> requested = unique;
  finest = layout.FinestLevel();
  auto withBase = [&]() {
    std::vector<std::uint32_t> pages = requested;
    for (const int f : faces)
    {
      for (int y = 0; y < (1 << base); ++y)
      {
        for (int x = 0; x < (1 << base); ++x)
        {
          pages.push_back(EncodePage(f, base, x, y));
        }
      }
    }
    return UniquePages(std::move(pages));
  };
  std::vector<std::uint32_t> pages = withBase();
  while (static_cast<int>(pages.size()) > layout.Capacity() && finest > base)
  {
    // The finest level in use gives way to its parent level (section 3.3.5).
    for (std::uint32_t& key : requested)
    {
      int f, level, x, y;
      DecodePage(key, f, level, x, y);
      if (level == finest)
      {
        key = EncodePage(f, level - 1, x / 2, y / 2);
      }
    }
    --finest;
    requested = UniquePages(std::move(requested));
    pages = withBase();
  }
  return pages;
}

SlotAssignment AssignSlots(const std::vector<std::uint32_t>& pages, std::map<std::uint32_t, int>& resident, int capacity)
{
  SlotAssignment assignment;
  assignment.SlotOf.assign(pages.size(), -1);
  // Per slot: 0 free, 1 holding a page not needed now, 2 taken.
  std::vector<char> taken(static_cast<size_t>(capacity), 0);
  for (const auto& [page, slot] : resident)
  {
    taken[static_cast<size_t>(slot)] = 1;
  }
  for (size_t i = 0; i < pages.size(); ++i)
  {
    const auto kept = resident.find(pages[i]);
    if (kept != resident.end())
    {
      assignment.SlotOf[i] = kept->second;
      taken[static_cast<size_t>(kept->second)] = 2;
    }
  }
  // Free slots first, then those of pages not needed now.
  for (char below = 1; below <= 2; ++below)
  {
    size_t free = 0;
    for (size_t i = 0; i < pages.size(); ++i)
    {
      if (assignment.SlotOf[i] >= 0)
      {
        continue;
      }
      while (free < taken.size() && taken[free] >= below)
      {
        ++free;
      }
      if (free == taken.size())
      {
        break;
      }
      assignment.SlotOf[i] = static_cast<int>(free);
      taken[free] = 2;
      assignment.Build.emplace_back(pages[i], static_cast<int>(free));
    }
  }
  std::vector<char> rebuilt(taken.size(), 0);
  for (const auto& entry : assignment.Build)
  {
    rebuilt[static_cast<size_t>(entry.second)] = 1;
  }
  for (auto page = resident.begin(); page != resident.end();)
  {
    page = rebuilt[static_cast<size_t>(page->second)] ? resident.erase(page) : std::next(page);
  }
  for (const auto& [page, slot] : assignment.Build)
  {
    resident[page] = slot;
  }
  return assignment;
}

std::vector<std::uint32_t> BuildPageTable(const std::vector<std::uint32_t>& pages, const std::vector<int>& slots,
  int faces, const PageLayout& layout)
{
  const int size = layout.TableSize();
  const int finest = layout.FinestLevel();
  std::vector<std::uint32_t> table(static_cast<size_t>(faces) * size * size, 0u);
  // Coarse pages first, so that finer ones over them take their cells.
  std::vector<size_t> order(pages.size());
  for (size_t i = 0; i < order.size(); ++i)
  {
    order[i] = i;
  }
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return ((pages[a] >> 22) & 15u) < ((pages[b] >> 22) & 15u);
  });
  for (const size_t i : order)
  {
    int f, level, x, y;
    DecodePage(pages[i], f, level, x, y);
    if (f >= faces)
    {
      continue;
    }
    const int cells = 1 << (finest - level);
    const std::uint32_t entry = PageTableEntry(slots[i], level);
    for (int cy = y * cells; cy < (y + 1) * cells; ++cy)
    {
      std::fill_n(&table[(static_cast<size_t>(f) * size + cy) * size + static_cast<size_t>(x) * cells],
        cells, entry);
    }
  }
  return table;
}

PageLookup LocatePage(const std::uint32_t* table, double x, double y, const PageLayout& layout)
{
  const int size = layout.TableSize();
  const int finest = layout.FinestLevel();
  x = ClampTexelPosition(x, layout.MaxResolution);
  y = ClampTexelPosition(y, layout.MaxResolution);
  // The finest cell the point's texel falls in, clamped to the face.
  const int cx = std::clamp(static_cast<int>(std::floor((x + 0.5) / layout.PageSize)), 0, size - 1);
  const int cy = std::clamp(static_cast<int>(std::floor((y + 0.5) / layout.PageSize)), 0, size - 1);
  const std::uint32_t entry = table[static_cast<size_t>(cy) * size + cx];
  PageLookup lookup;
  lookup.Slot = static_cast<int>(entry & 0xffffffu);
  lookup.Level = static_cast<int>(entry >> 24);
  const int coarser = finest - lookup.Level;
  lookup.Scale = std::ldexp(1.0, coarser);
  // The level's texel position, relative to the slot's first texel (the apron's).
  lookup.X = (x + 0.5) / lookup.Scale - 0.5 - (cx >> coarser) * layout.PageSize + layout.Apron;
  lookup.Y = (y + 0.5) / lookup.Scale - 0.5 - (cy >> coarser) * layout.PageSize + layout.Apron;
  return lookup;
}

namespace
{
ShadowParameters VirtualMap(ShadowParameters parameters)
{
  // LightSpaceShadow locates points on a map of the finest level's size, unclustered.
  parameters.MapSize = parameters.MaxResolution;
  parameters.Clusters = 0;
  return parameters;
}
}

ResolutionMatchedShadow::ResolutionMatchedShadow(const ShadowParameters& parameters,
  const ShadowCaster& caster, const Light& light, double step, int threads)
  : LightSpaceShadow(VirtualMap(parameters), caster, light, step)
  , Layout(PageLayout::Of(parameters))
{
  const int faces = static_cast<int>(this->Faces.size());
  if (this->Layout.BasePages(faces) > this->Layout.Capacity())
  {
    throw std::invalid_argument("the atlas holds " + std::to_string(this->Layout.Capacity()) +
      " pages, fewer than the base level's " + std::to_string(this->Layout.BasePages(faces)));
  }
  if (caster.View)
  {
    this->Analyse(*caster.View, threads);
  }
  std::vector<int> faceIndices(static_cast<size_t>(faces));
  for (int f = 0; f < faces; ++f)
  {
    faceIndices[static_cast<size_t>(f)] = f;
  }
  this->Pages = FitPages(this->Unique, faceIndices, this->Layout, this->Finest);
  std::vector<int> slots(this->Pages.size());
  for (size_t i = 0; i < slots.size(); ++i)
  {
    slots[i] = static_cast<int>(i);
  }
  this->Table = BuildPageTable(this->Pages, slots, faces, this->Layout);

  // Each page's texels, apron included, as the shadow map builds its texels.
  const int slotSize = this->Layout.SlotSize();
  const size_t slotTexels = static_cast<size_t>(slotSize) * slotSize;
  this->Depths.assign(this->Pages.size() * slotTexels, NoHit);
  ParallelFor(
    static_cast<int>(this->Pages.size()),
    [&](int page) {
      int f, level, px, py;
      DecodePage(this->Pages[static_cast<size_t>(page)], f, level, px, py);
      const double levelSize = this->Layout.LevelSize(level);
      for (int sy = 0; sy < slotSize; ++sy)
      {
        for (int sx = 0; sx < slotSize; ++sx)
        {
          const int vx = px * this->Layout.PageSize + sx - this->Layout.Apron;
          const int vy = py * this->Layout.PageSize + sy - this->Layout.Apron;
          glm::dvec3 origin, direction;
          this->Faces[f].TexelRay(2.0 * (vx + 0.5) / levelSize - 1.0, 2.0 * (vy + 0.5) / levelSize - 1.0, origin, direction);
          this->Depths[static_cast<size_t>(page) * slotTexels + static_cast<size_t>(sy) * slotSize + sx] =
            FirstOccluder(caster, parameters, step, caster.Empty, origin, direction);
        }
      }
    },
    threads);
}

void ResolutionMatchedShadow::Analyse(const Camera& view, int threads)
{
  const int downsample = std::max(1, this->Parameters.AnalysisDownsample);
  const int width = (view.GetWidth() + downsample - 1) / downsample;
  const int height = (view.GetHeight() + downsample - 1) / downsample;
  std::vector<AnalysisTexel> texels(static_cast<size_t>(width) * height);
  ParallelFor(
    height,
    [&](int j) {
      for (int i = 0; i < width; ++i)
      {
        // The receiver the pixel shows: the first occluder along its ray, as a texel's.
        const Ray ray = view.RayThrough((i + 0.5) * downsample, (j + 0.5) * downsample);
        const float hit = FirstOccluder(this->Caster, this->Parameters, this->Step, this->Caster.Empty, ray.Origin, ray.Direction);
        if (hit == NoHit)
        {
          continue;
        }
        const glm::dvec3 p = ray.Origin + static_cast<double>(hit) * ray.Direction;
        AnalysisTexel& texel = texels[static_cast<size_t>(j) * width + i];
        texel.Receiver = p;
        texel.Face = ShadowMapFaceFor(this->Faces, p - this->Faces[0].Origin);
        double u = 0.0, v = 0.0, depth = 0.0;
        if (this->Faces[texel.Face].Project(p, u, v, depth) && std::abs(u) <= 1.0 && std::abs(v) <= 1.0)
        {
          texel.Valid = true;
          texel.At = glm::dvec2(0.5 * (u + 1.0) * this->Size - 0.5, 0.5 * (v + 1.0) * this->Size - 0.5);
        }
      }
    },
    threads);
  for (const AnalysisTexel& texel : texels)
  {
    if (texel.Valid)
    {
      this->Receivers.push_back(texel.Receiver);
    }
  }
  const std::vector<std::uint32_t> requests =
    PageRequests(texels, width, height, downsample, this->Layout, &this->Requested);
  this->AfterComponents =
    static_cast<long long>(std::count_if(requests.begin(), requests.end(), [](std::uint32_t r) { return r != NoPage; }));
  this->Unique = UniquePages(requests);
}

glm::dvec3 ResolutionMatchedShadow::MapVisibility(const MapPoint& point) const
{
  const PageLookup page = LocatePage(&this->Table[static_cast<size_t>(point.Face) * this->Layout.TableSize() *
                                       this->Layout.TableSize()],
    point.X, point.Y, this->Layout);
  const int slotSize = this->Layout.SlotSize();
  return glm::dvec3(FilterShadowMap(&this->Depths[static_cast<size_t>(page.Slot) * slotSize * slotSize], slotSize,
    page.X, page.Y, point.Depth - this->Parameters.Bias * this->Step, this->Parameters.Filter,
    point.Slope * page.Scale));
}

}
