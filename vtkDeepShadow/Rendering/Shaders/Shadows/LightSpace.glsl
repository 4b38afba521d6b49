// Common part of the light-space lookups (shadow map, deep shadow map, opacity levels,
// CSSM): where a world point falls on the faces of a light, then the technique's
// mapVisibility() there (ShadowMapFace::Project, ShadowMapFaceFor and
// LightSpaceShadow::Visibility / SurfaceVisibility in Core/Shadows/LightSpace.cxx are the CPU
// twins). Depths are linear, from the face's near boundary.
//@Dec
const int MaxShadowLights = 4;
uniform sampler2DArray u_shadowMap;   // layer ((slot * faces per light) + face) * layers per face + k
uniform int u_shadowFacesPerLight;    // 1, or 6 when some light needs a cube
uniform int u_shadowLayersPerFace;    // deep shadow map nodes, CSSM photons; else 1
uniform int u_shadowFaceCount[MaxShadowLights];
uniform int u_shadowPerspective[MaxShadowLights];
uniform vec3 u_shadowOrigin[MaxShadowLights];  // light position, or near-plane centre
uniform vec3 u_shadowForward[MaxShadowLights]; // single-face lights
uniform vec3 u_shadowRight[MaxShadowLights];
uniform vec3 u_shadowUp[MaxShadowLights];
uniform float u_shadowExtent[MaxShadowLights];
uniform float u_shadowNear[MaxShadowLights];
uniform float u_shadowSize;

ivec2 lightSpaceClamp(ivec2 texel)
{
  return clamp(texel, ivec2(0), ivec2(int(u_shadowSize) - 1));
}

// Bilinear weights of the texels i0, i0 + (1, 0), i0 + (0, 1) and i0 + (1, 1) around xy.
vec4 lightSpaceBilinear(vec2 xy, out ivec2 i0)
{
  i0 = ivec2(floor(xy));
  vec2 f = xy - vec2(i0);
  return vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
}

// The technique's lookup at texel position xy (texel centres at integers) of the face whose
// texels start at `layer`, for a point at `depth`; on a receiving surface, `slope` is its
// plane's depth change per texel (MapPoint::Slope), and texel t is compared at
// lightSpaceDepthAt(t).
vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope);

float lightSpaceDepthAt(vec2 texel, vec2 xy, float depth, vec2 slope)
{
  return depth + dot(slope, texel - xy);
}

// deepshadow::MaxReceiverSlope: the steepest receiver plane followed, in texel widths.
const float MaxReceiverSlope = 5.67;

// Texel position and depth of point d (relative to the face's origin) on a face; false
// behind it.
bool lightSpaceLocate(int slot, vec3 d, vec3 forward, vec3 right, vec3 up, out vec3 at)
{
  float z = dot(d, forward);
  float u, v;
  if (u_shadowPerspective[slot] != 0)
  {
    if (z <= 0.0)
    {
      return false;
    }
    u = dot(d, right) / (z * u_shadowExtent[slot]);
    v = dot(d, up) / (z * u_shadowExtent[slot]);
    at.z = length(d) - u_shadowNear[slot];
  }
  else
  {
    if (z < 0.0)
    {
      return false;
    }
    u = dot(d, right) / u_shadowExtent[slot];
    v = dot(d, up) / u_shadowExtent[slot];
    at.z = z;
  }
  at.xy = 0.5 * (vec2(u, v) + 1.0) * u_shadowSize - 0.5;
  return true;
}

// deepshadow::LightSpaceShadow::SurfaceVisibility: the receiver plane's depth per texel, from
// two steps of a texel's width along it located on the same face.
vec2 lightSpaceReceiverSlope(int slot, vec3 d, vec3 forward, vec3 right, vec3 up, vec3 at, vec3 normal)
{
  float z = u_shadowPerspective[slot] != 0 ? dot(d, forward) : 1.0;
  float texel = 2.0 * z * u_shadowExtent[slot] / u_shadowSize;
  vec3 e1 = normalize(cross(normal, abs(normal.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  vec3 e2 = cross(normal, e1);
  vec3 a, b;
  if (!lightSpaceLocate(slot, d + texel * e1, forward, right, up, a) ||
    !lightSpaceLocate(slot, d + texel * e2, forward, right, up, b))
  {
    return vec2(0.0);
  }
  vec3 d1 = a - at, d2 = b - at;
  float det = d1.x * d2.y - d1.y * d2.x;
  if (!(abs(det) > 1e-12))
  {
    return vec2(0.0);
  }
  vec2 slope = vec2(d1.z * d2.y - d2.z * d1.y, d1.x * d2.z - d2.x * d1.z) / det;
  float steepest = MaxReceiverSlope * texel;
  float length2 = dot(slope, slope);
  return length2 > steepest * steepest ? slope * (steepest / sqrt(length2)) : slope;
}

#ifdef LIGHT_SPACE_UPSTREAM
// The bricks of this volume that lie between this one and the light, drawn by other
// processes (vtkDeepShadowBrickExchange): their total transmittance per texel, one layer per
// face (slot * u_shadowFacesPerLight + face), bilinear as the maps are. LightSpaceBricks and
// deepshadow::UpstreamTransmittance (Core/Shadows/Bricks.h) fill it.
uniform sampler2DArray u_shadowUpstream;

vec3 lightSpaceUpstream(int layer, vec2 xy)
{
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  return w.x * texelFetch(u_shadowUpstream, ivec3(lightSpaceClamp(i0), layer), 0).rgb +
    w.y * texelFetch(u_shadowUpstream, ivec3(lightSpaceClamp(i0 + ivec2(1, 0)), layer), 0).rgb +
    w.z * texelFetch(u_shadowUpstream, ivec3(lightSpaceClamp(i0 + ivec2(0, 1)), layer), 0).rgb +
    w.w * texelFetch(u_shadowUpstream, ivec3(lightSpaceClamp(i0 + ivec2(1, 1)), layer), 0).rgb;
}
#endif

// receiverNormal: a mesh point's unit normal, or zero for a volume sample.
vec3 lightVisibility(int slot, vec3 position, vec3 toLight, float lightDistance, vec3 receiverNormal)
{
  vec3 d = position - u_shadowOrigin[slot];
  vec3 forward = u_shadowForward[slot], right = u_shadowRight[slot], up = u_shadowUp[slot];
  int face = 0;
  if (u_shadowFaceCount[slot] == 6)
  {
    // Cube faces in the order +x, -x, +y, -y, +z, -z.
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
  vec3 at;
  if (!lightSpaceLocate(slot, d, forward, right, up, at))
  {
    return vec3(1.0);
  }
  vec2 slope = receiverNormal != vec3(0.0)
    ? lightSpaceReceiverSlope(slot, d, forward, right, up, at, receiverNormal)
    : vec2(0.0);
  vec3 visibility = mapVisibility((slot * u_shadowFacesPerLight + face) * u_shadowLayersPerFace, at.xy, at.z, slope);
#ifdef LIGHT_SPACE_UPSTREAM
  visibility *= lightSpaceUpstream(slot * u_shadowFacesPerLight + face, at.xy);
#endif
  return visibility;
}
