#version 430 core
// Page requests of resolution-matched shadow maps (paper 004, section 3.3.2), the GPU half of
// deepshadow::PageRequests and UniquePages (Core/Shadows/ResolutionMatched.cxx), one stage
// per program (PAGE_STAGE):
//   0: per analysis pixel and shadowed light, the page its receiver needs (eq. 1);
//   1: connected components and compaction: a request its left or lower neighbour makes
//      too is dropped, the rest appended to the list;
//   2: one step (u_k, u_j) of a bitonic sort of the list, padded with NoPage;
//   3: unique: the first of each run of equal requests, appended to the unique list.
#if PAGE_STAGE < 2
layout(local_size_x = 8, local_size_y = 8) in;
#else
layout(local_size_x = 64) in;
#endif
//DeepShadow::Locate::Dec
const uint NoPage = 0xffffffffu;
uniform ivec2 u_analysisSize;
layout(std430, binding = 0) buffer Requests
{
  uint requests[]; // per shadowed light, per analysis pixel (row by row)
} u_requests;
layout(std430, binding = 1) buffer List
{
  uint count;
  uint keys[];
} u_list;
layout(std430, binding = 2) buffer Unique
{
  uint count;
  uint valid; // pixels that asked for a page (before connected components)
  uint keys[];
} u_unique;

#if PAGE_STAGE == 0
uniform sampler2DArray u_hits; // distance to the first occluder along each pixel's ray
uniform mat4 u_inverseViewProjection;
uniform vec2 u_viewport;
uniform int u_downsample;
uniform int u_pageSize;
uniform int u_finestLevel;
uniform int u_baseLevel;
const float NoHit = 3.4028235e38;

// The receiver of analysis pixel `pixel` on the faces of light `slot`: its face and
// finest-level texel position; false if it sees none, or if it lies outside its face.
bool receiverAt(ivec2 pixel, int slot, out int face, out vec2 at)
{
  face = 0;
  at = vec2(0.0);
  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, u_analysisSize)))
  {
    return false;
  }
  float t = texelFetch(u_hits, ivec3(pixel, 0), 0).r;
  if (!(t < NoHit))
  {
    return false;
  }
  vec2 ndc = 2.0 * (vec2(pixel) + 0.5) * float(u_downsample) / u_viewport - 1.0;
  vec4 nearPoint = u_inverseViewProjection * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = u_inverseViewProjection * vec4(ndc, 1.0, 1.0);
  vec3 origin = nearPoint.xyz / nearPoint.w;
  vec3 position = origin + t * normalize(farPoint.xyz / farPoint.w - origin);
  LightSpaceFace lightFace;
  vec3 d, point;
  if (!lightSpacePoint(slot, position, lightFace, d, face, point))
  {
    return false;
  }
  at = point.xy;
  return all(greaterThanEqual(at, vec2(-0.5))) && all(lessThanEqual(at, vec2(u_shadowSize - 0.5)));
}

// Of the forward and backward differences along `axis` on the same face, the shorter.
bool derivative(ivec2 pixel, int slot, int face, vec2 at, ivec2 axis, out vec2 d)
{
  bool found = false;
  d = vec2(0.0);
  for (int s = 1; s >= -1; s -= 2)
  {
    int otherFace;
    vec2 otherAt;
    if (receiverAt(pixel + s * axis, slot, otherFace, otherAt) && otherFace == face)
    {
      vec2 candidate = float(s) * (otherAt - at);
      if (!found || dot(candidate, candidate) < dot(d, d))
      {
        d = candidate;
        found = true;
      }
    }
  }
  return found;
}

// deepshadow::RequestLevel: eq. 1.
int requestLevel(vec2 dX, vec2 dY)
{
  float side = sqrt(abs(dX.x * dY.y - dX.y * dY.x));
  if (!(side >= 1.0))
  {
    return u_finestLevel;
  }
  int coarser = int(floor(log2(min(side, 1e9))));
  return clamp(u_finestLevel - coarser, u_baseLevel, u_finestLevel);
}

// deepshadow::PageAt.
uint pageAt(int face, int level, vec2 at)
{
  float span = float(u_pageSize) * exp2(float(u_finestLevel - level));
  vec2 position = clamp(at, vec2(-64.0), vec2(u_shadowSize + 64.0));
  ivec2 page = clamp(ivec2(floor((position + 0.5) / span)), ivec2(0), ivec2((1 << level) - 1));
  return (uint(face) << 26) | (uint(level) << 22) | (uint(page.y) << 11) | uint(page.x);
}

void main()
{
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, u_analysisSize)))
  {
    return;
  }
  for (int slot = 0; slot < LIGHT_SPACE_SLOTS; ++slot)
  {
    uint request = NoPage;
    int face;
    vec2 at;
    if (receiverAt(pixel, slot, face, at))
    {
      vec2 dX, dY;
      bool hasX = derivative(pixel, slot, face, at, ivec2(1, 0), dX);
      bool hasY = derivative(pixel, slot, face, at, ivec2(0, 1), dY);
      int level = u_finestLevel;
      if (hasX || hasY)
      {
        // One axis alone: a square footprint, the other side turned a quarter.
        dX = hasX ? dX : vec2(dY.y, -dY.x);
        dY = hasY ? dY : vec2(-dX.y, dX.x);
        level = requestLevel(dX / float(u_downsample), dY / float(u_downsample));
      }
      request = pageAt((slot * u_shadowFacesPerLight + face), level, at);
      atomicAdd(u_unique.valid, 1u);
    }
    u_requests.requests[(slot * u_analysisSize.y + pixel.y) * u_analysisSize.x + pixel.x] = request;
  }
}

#elif PAGE_STAGE == 1
void main()
{
  ivec3 id = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(id.xy, u_analysisSize)))
  {
    return;
  }
  int k = (id.z * u_analysisSize.y + id.y) * u_analysisSize.x + id.x;
  uint request = u_requests.requests[k];
  uint left = id.x > 0 ? u_requests.requests[k - 1] : NoPage;
  uint below = id.y > 0 ? u_requests.requests[k - u_analysisSize.x] : NoPage;
  if (request != NoPage && request != left && request != below)
  {
    u_list.keys[atomicAdd(u_list.count, 1u)] = request;
  }
}

#elif PAGE_STAGE == 2
uniform int u_k;
uniform int u_j;
uniform int u_length; // a power of two

void main()
{
  uint i = gl_GlobalInvocationID.x;
  uint other = i ^ uint(u_j);
  if (i >= uint(u_length) || other <= i)
  {
    return;
  }
  uint a = u_list.keys[i];
  uint b = u_list.keys[other];
  bool ascending = (i & uint(u_k)) == 0u;
  if ((a > b) == ascending)
  {
    u_list.keys[i] = b;
    u_list.keys[other] = a;
  }
}

#else
void main()
{
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_list.count)
  {
    return;
  }
  uint key = u_list.keys[i];
  if (key != NoPage && (i == 0u || u_list.keys[i - 1u] != key))
  {
    u_unique.keys[atomicAdd(u_unique.count, 1u)] = key;
  }
}
#endif
