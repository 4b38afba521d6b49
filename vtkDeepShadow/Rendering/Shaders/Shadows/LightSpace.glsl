// Common part of the light-space lookups (shadow map, deep shadow map, opacity levels,
// CSSM): where a world point falls on the faces of a light, then the technique's
// mapVisibility() there (ShadowMapFace::Project, ShadowMapFaceFor and
// LightSpaceShadow::Visibility / SurfaceVisibility in Core/Shadows/LightSpace.cxx are the CPU
// twins). Depths are linear, from the face's near boundary.
//
// Only the kinds of face the lights use are compiled (LightSpaceSource in
// vtkDeepShadowLightSpaceTechnique.cxx defines LIGHT_SPACE_PERSPECTIVE, _ORTHOGRAPHIC and
// _CUBES, and LIGHT_SPACE_SLOTS, the lights casting shadows): llvmpipe runs both sides of
// every branch, masked, so a branch no light takes still costs (the cube and perspective code
// cost 0.11 of an unshadowed frame on the box).
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

// Texel `texel` of layer `layer` of the maps, the nearest edge texel outside them (as
// lightSpaceClamp): a nearest sample at its centre, which the sampler clamps to the edge.
// The same value as texelFetch, which costs llvmpipe more (its bounds checks): the deep
// shadow map's frame on the box went from 1.58 to 1.49 times the unshadowed one.
vec4 lightSpaceTexel(ivec2 texel, int layer)
{
  return textureLod(u_shadowMap, vec3((vec2(texel) + 0.5) / u_shadowSize, float(layer)), 0.0);
}

// Bilinear weights of the texels i0, i0 + (1, 0), i0 + (0, 1) and i0 + (1, 1) around xy.
vec4 lightSpaceBilinear(vec2 xy, out ivec2 i0)
{
  i0 = ivec2(floor(xy));
  vec2 f = xy - vec2(i0);
  return vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
}

#ifndef LIGHT_SPACE_LOCATE_ONLY
// The technique's lookup at texel position xy (texel centres at integers) of the face whose
// texels start at `layer`, for a point at `depth`; on a receiving surface, `slope` is its
// plane's depth change per texel (MapPoint::Slope), and texel t is compared at
// lightSpaceDepthAt(t). (Without it, LIGHT_SPACE_LOCATE_ONLY: where points fall, for
// resolution-matched maps' page requests.)
vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope);
#endif

float lightSpaceDepthAt(vec2 texel, vec2 xy, float depth, vec2 slope)
{
  return depth + dot(slope, texel - xy);
}

// deepshadow::MaxReceiverSlope: the steepest receiver plane followed, in texel widths.
const float MaxReceiverSlope = 5.67;

// One face as the lookup sees it (deepshadow::ShadowMapFace).
struct LightSpaceFace
{
  bool perspective;
  vec3 origin, forward, right, up;
  float extent, near;
};

// Whether the face is perspective; a constant where only one kind is compiled, so the other
// kind's code folds away.
bool lightSpacePerspective(LightSpaceFace face)
{
#if defined(LIGHT_SPACE_PERSPECTIVE) && defined(LIGHT_SPACE_ORTHOGRAPHIC)
  return face.perspective;
#elif defined(LIGHT_SPACE_PERSPECTIVE)
  return true;
#else
  return false;
#endif
}

// The face of light slot `slot` (its first, for a cube), and its number of faces.
// llvmpipe loads a uniform at a constant index once for all fragments, but one at a computed
// index fragment by fragment: they are picked among constant-index loads of the
// LIGHT_SPACE_SLOTS lights that cast shadows (see also lightVisibility). Unrolled by hand: a
// loop that runs no time still costs llvmpipe one masked pass.
LightSpaceFace lightSpaceFaceAt(const int slot)
{
  return LightSpaceFace(u_shadowPerspective[slot] != 0, u_shadowOrigin[slot], u_shadowForward[slot],
    u_shadowRight[slot], u_shadowUp[slot], u_shadowExtent[slot], u_shadowNear[slot]);
}

LightSpaceFace lightSpaceFaceOf(int slot)
{
  LightSpaceFace face = lightSpaceFaceAt(0);
#if LIGHT_SPACE_SLOTS > 1
  face = slot == 1 ? lightSpaceFaceAt(1) : face;
#endif
#if LIGHT_SPACE_SLOTS > 2
  face = slot == 2 ? lightSpaceFaceAt(2) : face;
#endif
#if LIGHT_SPACE_SLOTS > 3
  face = slot == 3 ? lightSpaceFaceAt(3) : face;
#endif
  return face;
}

int lightSpaceFaceCountOf(int slot)
{
  int count = u_shadowFaceCount[0];
#if LIGHT_SPACE_SLOTS > 1
  count = slot == 1 ? u_shadowFaceCount[1] : count;
#endif
#if LIGHT_SPACE_SLOTS > 2
  count = slot == 2 ? u_shadowFaceCount[2] : count;
#endif
#if LIGHT_SPACE_SLOTS > 3
  count = slot == 3 ? u_shadowFaceCount[3] : count;
#endif
  return count;
}

// Texel position and depth of point d (relative to the face's origin) on a face; false
// behind it.
bool lightSpaceLocate(LightSpaceFace face, vec3 d, out vec3 at)
{
  float z = dot(d, face.forward);
  float u, v;
  if (lightSpacePerspective(face))
  {
    if (z <= 0.0)
    {
      return false;
    }
    u = dot(d, face.right) / (z * face.extent);
    v = dot(d, face.up) / (z * face.extent);
    at.z = length(d) - face.near;
  }
  else
  {
    if (z < 0.0)
    {
      return false;
    }
    u = dot(d, face.right) / face.extent;
    v = dot(d, face.up) / face.extent;
    at.z = z;
  }
  at.xy = 0.5 * (vec2(u, v) + 1.0) * u_shadowSize - 0.5;
  return true;
}

// deepshadow::LightSpaceShadow::SurfaceVisibility: the receiver plane's depth per texel, from
// two steps of a texel's width along it located on the same face.
vec2 lightSpaceReceiverSlope(LightSpaceFace face, vec3 d, vec3 at, vec3 normal)
{
  float z = lightSpacePerspective(face) ? dot(d, face.forward) : 1.0;
  float texel = 2.0 * z * face.extent / u_shadowSize;
  vec3 e1 = normalize(cross(normal, abs(normal.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  vec3 e2 = cross(normal, e1);
  vec3 a, b;
  if (!lightSpaceLocate(face, d + texel * e1, a) || !lightSpaceLocate(face, d + texel * e2, b))
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

// Where `position` falls on the faces of light slot `slot` (unclustered): its face (a cube's
// face picked by the major axis, in the order +x, -x, +y, -y, +z, -z), d relative to its
// origin, the cube face's index (0 otherwise) and its texel position and depth; false behind.
bool lightSpacePoint(int slot, vec3 position, out LightSpaceFace face, out vec3 d, out int cubeFace, out vec3 at)
{
  face = lightSpaceFaceOf(slot);
  d = position - face.origin;
  cubeFace = 0;
#ifdef LIGHT_SPACE_CUBES
  if (lightSpaceFaceCountOf(slot) == 6)
  {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z)
    {
      cubeFace = d.x >= 0.0 ? 0 : 1;
    }
    else if (a.y >= a.z)
    {
      cubeFace = d.y >= 0.0 ? 2 : 3;
    }
    else
    {
      cubeFace = d.z >= 0.0 ? 4 : 5;
    }
    vec3 axes[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
      vec3(0, 0, 1), vec3(0, 0, -1));
    face.forward = axes[cubeFace];
    vec3 helper = abs(face.forward.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    face.right = normalize(cross(face.forward, helper));
    face.up = cross(face.right, face.forward);
  }
#endif
  return lightSpaceLocate(face, d, at);
}

#ifndef LIGHT_SPACE_LOCATE_ONLY
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

#ifdef LIGHT_SPACE_CLUSTERS
// Clustered faces (deepshadow::ClusterFaces): face f of slot s at index s * MaxClusterFaces + f.
// A light that is not clustered has its one face there, unwindowed (LightSpaceShadow's
// unclustered lookup); one that needs a cube goes the unclustered way (LIGHT_SPACE_CUBES).
const int MaxClusterFaces = 8;
uniform int u_shadowClusters[MaxShadowLights]; // faces of the light in the loop; 0: a cube
uniform int u_shadowClusterWindowed[MaxShadowLights * MaxClusterFaces]; // 0: an unclustered face
uniform int u_shadowClusterPerspective[MaxShadowLights * MaxClusterFaces];
uniform vec3 u_shadowClusterOrigin[MaxShadowLights * MaxClusterFaces];
uniform vec3 u_shadowClusterForward[MaxShadowLights * MaxClusterFaces];
uniform vec3 u_shadowClusterRight[MaxShadowLights * MaxClusterFaces];
uniform vec3 u_shadowClusterUp[MaxShadowLights * MaxClusterFaces];
uniform float u_shadowClusterExtent[MaxShadowLights * MaxClusterFaces];
uniform float u_shadowClusterNear[MaxShadowLights * MaxClusterFaces];
uniform float u_shadowClusterStart[MaxShadowLights * MaxClusterFaces]; // depth of its box's nearest corner

// deepshadow::LightSpaceShadow::Visibility, clustered: what every cluster casts along the
// light's ray; a cluster whose face does not see the point (InsideFace), or that lies beyond
// a volume sample, casts nothing there.
vec3 lightSpaceClusters(int slot, vec3 position, vec3 receiverNormal)
{
  vec3 visibility = vec3(1.0);
  for (int f = 0; f < u_shadowClusters[slot]; ++f)
  {
    int i = slot * MaxClusterFaces + f;
    LightSpaceFace face = LightSpaceFace(u_shadowClusterPerspective[i] != 0, u_shadowClusterOrigin[i],
      u_shadowClusterForward[i], u_shadowClusterRight[i], u_shadowClusterUp[i], u_shadowClusterExtent[i],
      u_shadowClusterNear[i]);
    vec3 d = position - face.origin;
    vec3 at;
    if (!lightSpaceLocate(face, d, at) ||
      (u_shadowClusterWindowed[i] != 0 &&
        (any(lessThan(at.xy, vec2(-0.5))) || any(greaterThan(at.xy, vec2(u_shadowSize - 0.5))) ||
          (receiverNormal == vec3(0.0) && at.z < u_shadowClusterStart[i]))))
    {
      continue;
    }
    vec2 slope = receiverNormal != vec3(0.0) ? lightSpaceReceiverSlope(face, d, at, receiverNormal) : vec2(0.0);
    visibility *= mapVisibility((slot * u_shadowFacesPerLight + f) * u_shadowLayersPerFace, at.xy, at.z, slope);
  }
  return visibility;
}
#endif

// receiverNormal: a mesh point's unit normal, or zero for a volume sample.
vec3 lightVisibility(int slot, vec3 position, vec3 toLight, float lightDistance, vec3 receiverNormal)
{
#if LIGHT_SPACE_SLOTS == 1
  // The one light that casts shadows: every slot index below is a constant.
  slot = 0;
#endif
#ifdef LIGHT_SPACE_CLUSTERS
  // One path for every light (a light with one unclustered face is a single whole face):
  // two inlined lookups cost llvmpipe 0.3 of an unshadowed frame even where one never runs.
#ifdef LIGHT_SPACE_CUBES
  if (u_shadowClusters[slot] > 0)
#endif
  {
    return lightSpaceClusters(slot, position, receiverNormal);
  }
#endif
#if !defined(LIGHT_SPACE_CLUSTERS) || defined(LIGHT_SPACE_CUBES)
  LightSpaceFace face;
  vec3 d, at;
  int cubeFace;
  if (!lightSpacePoint(slot, position, face, d, cubeFace, at))
  {
    return vec3(1.0);
  }
  vec2 slope = receiverNormal != vec3(0.0) ? lightSpaceReceiverSlope(face, d, at, receiverNormal) : vec2(0.0);
  vec3 visibility = mapVisibility((slot * u_shadowFacesPerLight + cubeFace) * u_shadowLayersPerFace, at.xy, at.z, slope);
#ifdef LIGHT_SPACE_UPSTREAM
  visibility *= lightSpaceUpstream(slot * u_shadowFacesPerLight + cubeFace, at.xy);
#endif
  return visibility;
#endif
}
#endif
