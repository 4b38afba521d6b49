// Shadow technique "shadowmap": per light up to six faces (one orthographic for directional
// lights, one perspective for positional lights outside the volume's bounding sphere, a cube
// inside it), each a layer of u_shadowMap holding the depth of the first sample above the
// threshold; percentage-closer filtered (ShadowMapFace, ShadowMapFaceFor and
// FilterShadowMap in Core/Shadows.cxx are the CPU twins). SHADOW_FILTER and the Poisson disc
// are defined by the technique from Core's tables.
//@Dec
const int MaxShadowLights = 4;
uniform sampler2DArray u_shadowMap;          // R32F depths, layer = slot * layers + face
uniform int u_shadowLayersPerLight;          // 1, or 6 when some light needs a cube
uniform int u_shadowSlot[MaxLights];         // -1: the light casts no shadow
uniform float u_shadowAttenuation[MaxLights];
uniform int u_shadowFaceCount[MaxShadowLights];
uniform int u_shadowPerspective[MaxShadowLights];
uniform vec3 u_shadowOrigin[MaxShadowLights];  // light position, or near-plane centre
uniform vec3 u_shadowForward[MaxShadowLights]; // single-face lights
uniform vec3 u_shadowRight[MaxShadowLights];
uniform vec3 u_shadowUp[MaxShadowLights];
uniform float u_shadowExtent[MaxShadowLights];
uniform float u_shadowSize;
uniform float u_shadowBias;                  // world units

float shadowLit(int layer, ivec2 texel, float depth)
{
  texel = clamp(texel, ivec2(0), ivec2(int(u_shadowSize) - 1));
  return depth <= texelFetch(u_shadowMap, ivec3(texel, layer), 0).r ? 1.0 : 0.0;
}

float filteredShadow(int layer, vec2 xy, float depth)
{
  ivec2 nearest = ivec2(floor(xy + 0.5));
#if SHADOW_FILTER == 0
  return shadowLit(layer, nearest, depth);
#elif SHADOW_FILTER == 1
  ivec2 i0 = ivec2(floor(xy));
  vec2 f = xy - vec2(i0);
  return (1.0 - f.x) * (1.0 - f.y) * shadowLit(layer, i0, depth) +
    f.x * (1.0 - f.y) * shadowLit(layer, i0 + ivec2(1, 0), depth) +
    (1.0 - f.x) * f.y * shadowLit(layer, i0 + ivec2(0, 1), depth) +
    f.x * f.y * shadowLit(layer, i0 + ivec2(1, 1), depth);
#elif SHADOW_FILTER == 2
  float sum = 0.0;
  for (int dj = -1; dj <= 1; ++dj)
  {
    for (int di = -1; di <= 1; ++di)
    {
      sum += shadowLit(layer, nearest + ivec2(di, dj), depth);
    }
  }
  return sum / 9.0;
#else
  float sum = 0.0;
  for (int k = 0; k < POISSON_TAPS; ++k)
  {
    sum += shadowLit(layer, ivec2(floor(xy + POISSON_DISC[k] + 0.5)), depth);
  }
  return sum / float(POISSON_TAPS);
#endif
}

float mapVisibility(int slot, vec3 position)
{
  vec3 d = position - u_shadowOrigin[slot];
  vec3 forward = u_shadowForward[slot], right = u_shadowRight[slot], up = u_shadowUp[slot];
  int face = 0;
  if (u_shadowFaceCount[slot] == 6)
  {
    // Cube faces in the order +x, -x, +y, -y, +z, -z (deepshadow::ShadowMapFaceFor).
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z)
    {
      face = d.x >= 0.0 ? 0 : 1;
    }
    else if (a.y >= a.z)
    {
      face = d.y >= 0.0 ? 2 : 3;
    }
    else
    {
      face = d.z >= 0.0 ? 4 : 5;
    }
    vec3 axes[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
      vec3(0, 0, 1), vec3(0, 0, -1));
    forward = axes[face];
    vec3 helper = abs(forward.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    right = normalize(cross(forward, helper));
    up = cross(right, forward);
  }
  float z = dot(d, forward);
  float u, v, depth;
  if (u_shadowPerspective[slot] != 0)
  {
    if (z <= 0.0)
    {
      return 1.0;
    }
    u = dot(d, right) / (z * u_shadowExtent[slot]);
    v = dot(d, up) / (z * u_shadowExtent[slot]);
    depth = length(d);
  }
  else
  {
    if (z < 0.0)
    {
      return 1.0;
    }
    u = dot(d, right) / u_shadowExtent[slot];
    v = dot(d, up) / u_shadowExtent[slot];
    depth = z;
  }
  vec2 xy = 0.5 * (vec2(u, v) + 1.0) * u_shadowSize - 0.5;
  return filteredShadow(slot * u_shadowLayersPerLight + face, xy, depth - u_shadowBias);
}
//@Impl
    if (u_shadowSlot[i] >= 0)
    {
      float visibility = mapVisibility(u_shadowSlot[i], position);
      attenuation *= 1.0 - u_shadowAttenuation[i] * (1.0 - visibility);
    }
