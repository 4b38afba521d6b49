#include "LightSpaceBricks.h"

#include "GL/UniformSink.h"
#include "vtkDeepShadowBrickExchange.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>

namespace deepshadow
{
namespace
{
double NowMilliseconds()
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// What each brick sends at the start of a frame: its box, then the map's shape, then a
// signature of its lights (the scan's order depends on them: bricks must agree).
constexpr size_t BoxValues = 6;
constexpr size_t ShapeValues = 3;
constexpr size_t FrameValues = BoxValues + ShapeValues + 1;

// 24 bits of the lights' placement, exact as a float.
float LightSignature(const std::vector<Light>& lights)
{
  std::uint32_t hash = 2166136261u; // FNV-1a
  for (const Light& light : lights)
  {
    const float values[7] = { light.Positional ? 1.0f : 0.0f, static_cast<float>(light.Position.x),
      static_cast<float>(light.Position.y), static_cast<float>(light.Position.z),
      static_cast<float>(light.FocalPoint.x), static_cast<float>(light.FocalPoint.y),
      static_cast<float>(light.FocalPoint.z) };
    const auto* bytes = reinterpret_cast<const unsigned char*>(values);
    for (size_t i = 0; i < sizeof(values); ++i)
    {
      hash = (hash ^ bytes[i]) * 16777619u;
    }
  }
  return static_cast<float>(hash & 0xFFFFFFu);
}

// Texel rays and boxes are in world units: boxes that share a face agree on it to float
// precision of their coordinates.
double SharedFaceTolerance(const BrickBox& all)
{
  return 1e-5 * std::max(1.0, glm::length(all.Max - all.Min));
}
}

LightSpaceBricks::~LightSpaceBricks() = default;

void LightSpaceBricks::SetExchange(vtkDeepShadowBrickExchange* exchange)
{
  this->Exchanger = exchange;
}

vtkDeepShadowBrickExchange* LightSpaceBricks::GetExchange() const
{
  return this->Exchanger;
}

bool LightSpaceBricks::BeginFrame(
  CasterBounds& bounds, int mapSize, const std::vector<Light>& slotLights, int channels, std::string& problem)
{
  // Until this frame is known to exchange: back to the brick's own faces, a change if it
  // exchanged before.
  const bool wasActive = this->Active;
  this->UnionMoved = wasActive;
  this->Active = false;
  if (!this->Exchanger || this->Exchanger->GetNumberOfBricks() <= 1)
  {
    return false;
  }
  this->Exchanger->BeginFrame();
  BrickBox local;
  for (const glm::dvec3& corner : bounds.Corners)
  {
    local = local.Union(BrickBox{ corner, corner });
  }
  if (bounds.Corners.empty())
  {
    local = BrickBox{ bounds.Centre - bounds.Radius, bounds.Centre + bounds.Radius };
  }
  std::vector<float> mine{ static_cast<float>(local.Min.x), static_cast<float>(local.Min.y),
    static_cast<float>(local.Min.z), static_cast<float>(local.Max.x), static_cast<float>(local.Max.y),
    static_cast<float>(local.Max.z), static_cast<float>(mapSize), static_cast<float>(slotLights.size()),
    static_cast<float>(channels), LightSignature(slotLights) };
  std::vector<float> all;
  const double start = NowMilliseconds();
  const bool gathered = this->Exchanger->AllGather(mine, all);
  const size_t bricks = static_cast<size_t>(this->Exchanger->GetNumberOfBricks());
  this->Exchanger->Account(static_cast<long long>((bricks - 1) * mine.size() * sizeof(float)),
    static_cast<int>(bricks - 1), NowMilliseconds() - start);
  if (!gathered || all.size() != bricks * mine.size())
  {
    problem = "the bricks' boxes could not be gathered";
    return false;
  }
  this->Boxes.assign(bricks, BrickBox{});
  this->LightsAgree = true;
  BrickBox everything;
  for (size_t b = 0; b < bricks; ++b)
  {
    const float* v = all.data() + b * mine.size();
    if (!std::equal(v + BoxValues, v + BoxValues + ShapeValues, mine.data() + BoxValues))
    {
      problem = "the bricks disagree on the map size, the shadow-casting lights or colour (brick " +
        std::to_string(b) + ")";
      return false;
    }
    this->LightsAgree = this->LightsAgree && v[FrameValues - 1] == mine[FrameValues - 1];
    this->Boxes[b] = BrickBox{ glm::dvec3(v[0], v[1], v[2]), glm::dvec3(v[3], v[4], v[5]) };
    everything = everything.Union(this->Boxes[b]);
  }
  if (!everything.IsValid())
  {
    return false;
  }
  this->LocalBrick = this->Exchanger->GetLocalBrick();
  this->UnionMoved = !wasActive || everything.Min != this->LastUnion.Min || everything.Max != this->LastUnion.Max;
  this->LastUnion = everything;
  bounds.Centre = 0.5 * (everything.Min + everything.Max);
  bounds.Radius = 0.5 * glm::length(everything.Max - everything.Min);
  bounds.Corners.clear();
  for (int corner = 0; corner < 8; ++corner)
  {
    bounds.Corners.emplace_back(corner & 1 ? everything.Max.x : everything.Min.x,
      corner & 2 ? everything.Max.y : everything.Min.y, corner & 4 ? everything.Max.z : everything.Min.z);
  }
  this->Active = true;
  return true;
}

void LightSpaceBricks::ReadTotals(
  vtkOpenGLRenderWindow* window, unsigned int totals, int size, int layers, int channels)
{
  std::vector<float> rgba(static_cast<size_t>(size) * size * layers * 4);
  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  const int unit = units->Allocate();
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, totals);
  glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA, GL_FLOAT, rgba.data());
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  units->Free(unit);
  this->Size = size;
  this->Layers = layers;
  this->Channels = channels;
  this->Totals.resize(static_cast<size_t>(size) * size * layers * channels);
  for (size_t texel = 0; texel < rgba.size() / 4; ++texel)
  {
    for (int c = 0; c < channels; ++c)
    {
      this->Totals[texel * channels + c] = rgba[texel * 4 + c];
    }
  }
}

bool LightSpaceBricks::Exchange(vtkOpenGLRenderWindow* window, const std::vector<Light>& slotLights,
  int facesPerLight, std::string& problem)
{
  // Per light (slot): its faces' texels.
  const size_t perFace = static_cast<size_t>(this->Size) * this->Size * this->Channels;
  const size_t perSlot = perFace * facesPerLight;
  const size_t slots = std::min(slotLights.size(), perSlot ? this->Totals.size() / perSlot : 0);
  const double tolerance = SharedFaceTolerance(this->LastUnion);
  // Scanned along each light's order of the bricks where every brick can: the decision
  // rests on what every brick gathered at BeginFrame, so all take the same path.
  bool scan = this->Exchanger->GetScan() && this->Exchanger->CanSendReceive() && this->LightsAgree;
  if (scan)
  {
    this->UpdateOrders(slotLights, slots, tolerance);
    for (const std::vector<int>& order : this->Orders)
    {
      scan = scan && !order.empty();
    }
  }
  std::vector<float> upstream(this->Totals.size(), 1.0f);
  const double start = NowMilliseconds();
  const bool exchanged = scan ? this->Scan(this->Orders, perSlot, upstream)
                              : this->Gather(slotLights, slots, perSlot, tolerance, upstream);
  this->Exchanger->Account(0, 0, NowMilliseconds() - start);
  if (!exchanged)
  {
    problem = "the bricks' light-space totals could not be exchanged";
    return false;
  }
  this->Exchanger->SetLastScanned(scan);
  if (upstream == this->Upstream && this->Texture && this->TextureSize == this->Size &&
    this->TextureLayers == this->Layers)
  {
    return true;
  }
  this->Upstream = std::move(upstream);
  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  const int unit = units->Allocate();
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
  if (!this->Texture || this->TextureSize != this->Size || this->TextureLayers != this->Layers)
  {
    if (this->Texture)
    {
      glDeleteTextures(1, &this->Texture);
    }
    glGenTextures(1, &this->Texture);
    glBindTexture(GL_TEXTURE_2D_ARRAY, this->Texture);
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RGBA32F, this->Size, this->Size, this->Layers);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    this->TextureSize = this->Size;
    this->TextureLayers = this->Layers;
  }
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->Texture);
  std::vector<float> rgba(this->Upstream.size() / this->Channels * 4, 1.0f);
  for (size_t texel = 0; texel < rgba.size() / 4; ++texel)
  {
    for (int c = 0; c < 3; ++c)
    {
      rgba[texel * 4 + c] = this->Upstream[texel * this->Channels + std::min(c, this->Channels - 1)];
    }
  }
  glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, this->Size, this->Size, this->Layers, GL_RGBA,
    GL_FLOAT, rgba.data());
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  units->Free(unit);
  this->Version += 1.0;
  return true;
}

void LightSpaceBricks::UpdateOrders(const std::vector<Light>& slotLights, size_t slots, double tolerance)
{
  // The kd tree is rebuilt for each light (O(bricks^2) splits tried at each level): only when
  // the boxes or a light moved, not every frame.
  std::vector<double> key;
  for (const BrickBox& box : this->Boxes)
  {
    key.insert(key.end(), { box.Min.x, box.Min.y, box.Min.z, box.Max.x, box.Max.y, box.Max.z });
  }
  for (size_t slot = 0; slot < slots; ++slot)
  {
    const Light& light = slotLights[slot];
    key.insert(key.end(), { light.Positional ? 1.0 : 0.0, light.Position.x, light.Position.y, light.Position.z,
                            light.FocalPoint.x, light.FocalPoint.y, light.FocalPoint.z });
  }
  if (key == this->OrdersKey)
  {
    return;
  }
  this->OrdersKey = std::move(key);
  this->Orders.clear();
  for (size_t slot = 0; slot < slots; ++slot)
  {
    this->Orders.push_back(LightOrder(this->Boxes, slotLights[slot], tolerance));
  }
}

bool LightSpaceBricks::Scan(const std::vector<std::vector<int>>& orders, size_t perSlot, std::vector<float>& upstream)
{
  vtkDeepShadowBrickExchange* exchanger = this->Exchanger;
  long long bytes = 0;
  int messages = 0;
  const ScanMessage message = [&](int to, const std::vector<float>& send, int from, std::vector<float>& received,
                                bool sendFirst, int tag) {
    bytes += from >= 0 ? static_cast<long long>(received.size() * sizeof(float)) : 0;
    messages += from >= 0 ? 1 : 0;
    return exchanger->SendReceive(to, send, from, received, sendFirst, tag);
  };
  // An empty brick casts nothing, whatever its lookups read.
  const bool empty = !this->Boxes[static_cast<size_t>(this->LocalBrick)].IsValid();
  const int rounds = ScanRounds(static_cast<int>(this->Boxes.size()));
  for (size_t slot = 0; slot < orders.size(); ++slot)
  {
    const auto from = this->Totals.begin() + static_cast<std::ptrdiff_t>(slot * perSlot);
    const std::vector<float> local = empty
      ? std::vector<float>(perSlot, 1.0f)
      : std::vector<float>(from, from + static_cast<std::ptrdiff_t>(perSlot));
    std::vector<float> product;
    const int tag = static_cast<int>(slot) * rounds; // each slot's rounds their own tags
    if (!ExclusiveProductScan(orders[slot], this->LocalBrick, local, tag, message, product))
    {
      return false;
    }
    std::copy(product.begin(), product.end(), upstream.begin() + static_cast<std::ptrdiff_t>(slot * perSlot));
  }
  exchanger->Account(bytes, messages, 0.0);
  this->Overlap = false; // the bricks had an order
  return true;
}

bool LightSpaceBricks::Gather(const std::vector<Light>& slotLights, size_t slots, size_t perSlot, double tolerance,
  std::vector<float>& upstream)
{
  std::vector<float> all;
  const bool gathered = this->Exchanger->AllGather(this->Totals, all);
  const size_t bricks = this->Boxes.size();
  if (!gathered || all.size() != bricks * this->Totals.size())
  {
    return false;
  }
  this->Exchanger->Account(static_cast<long long>((bricks - 1) * this->Totals.size() * sizeof(float)),
    static_cast<int>(bricks - 1), 0.0);
  // Per light (slot): every brick's texels, then their product in front of ours.
  this->Overlap = false;
  for (size_t slot = 0; slot < slots; ++slot)
  {
    std::vector<float> light(bricks * perSlot);
    for (size_t b = 0; b < bricks; ++b)
    {
      const float* from = all.data() + b * this->Totals.size() + slot * perSlot;
      std::copy(from, from + perSlot, light.begin() + static_cast<std::ptrdiff_t>(b * perSlot));
    }
    bool overlapping = false;
    const std::vector<float> product =
      UpstreamTransmittance(light, perSlot, this->LocalBrick, this->Boxes, slotLights[slot], tolerance, overlapping);
    std::copy(product.begin(), product.end(), upstream.begin() + static_cast<std::ptrdiff_t>(slot * perSlot));
    this->Overlap = this->Overlap || overlapping;
  }
  return true;
}

void LightSpaceBricks::BindLookup(UniformSink& sink, vtkOpenGLRenderWindow* window)
{
  this->Window = window;
  this->Unit = window->GetTextureUnitManager()->Allocate();
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + this->Unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->Texture);
  sink.Set("u_shadowUpstream", this->Unit);
}

void LightSpaceBricks::UnbindLookup()
{
  if (this->Unit >= 0)
  {
    this->Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + this->Unit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    this->Window->GetTextureUnitManager()->Free(this->Unit);
    this->Unit = -1;
  }
}

void LightSpaceBricks::Release()
{
  if (this->Texture)
  {
    glDeleteTextures(1, &this->Texture);
    this->Texture = 0;
  }
  this->TextureSize = this->TextureLayers = 0;
  this->Upstream.clear();
  this->Totals.clear();
}

}
