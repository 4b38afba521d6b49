// Common part of the light-space lookups (shadow map, deep shadow map, opacity levels,
// CSSM): where a world point falls on the faces of a light, then the technique's
// mapVisibility() there (ShadowMapFace::Project, ShadowMapFaceFor and
// LightSpaceShadow::Visibility in Core/Shadows/LightSpace.cxx are the CPU twins). Depths
// are linear, from the face's near boundary.
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
// texels start at `layer`, for a point at `depth`.
vec3 mapVisibility(int layer, vec2 xy, float depth);

vec3 lightVisibility(int slot, vec3 position, vec3 toLight, float lightDistance)
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
  float z = dot(d, forward);
  float u, v, depth;
  if (u_shadowPerspective[slot] != 0)
  {
    if (z <= 0.0)
    {
      return vec3(1.0);
    }
    u = dot(d, right) / (z * u_shadowExtent[slot]);
    v = dot(d, up) / (z * u_shadowExtent[slot]);
    depth = length(d) - u_shadowNear[slot];
  }
  else
  {
    if (z < 0.0)
    {
      return vec3(1.0);
    }
    u = dot(d, right) / u_shadowExtent[slot];
    v = dot(d, up) / u_shadowExtent[slot];
    depth = z;
  }
  vec2 xy = 0.5 * (vec2(u, v) + 1.0) * u_shadowSize - 0.5;
  return mapVisibility((slot * u_shadowFacesPerLight + face) * u_shadowLayersPerFace, xy, depth);
}
