#version 430 core
// Build pass of the light-space techniques: one invocation per texel of one face of one
// light. It casts the texel's ray (ShadowMapFace::TexelRay), marches its samples as
// MarchTexelRay in Core/Shadows/LightSpace.cxx does, and hands them to the technique's
// runtime feature Build, which defines visitSample(), visitSkipped() (a run of empty blocks,
// at its last sample), visitSurface() (a casting surface's crossing, part Surface; feature
// Surfaces) and buildTexel() (which calls marchTexel(), once or more). A technique
// may defer a texel (deferTexel()) to a second dispatch over the deferred texels only
// (u_deferredPass = 1), for work that few texels need: in lockstep hardware, a texel that
// works longer inside the first dispatch keeps its neighbours waiting.
layout(local_size_x = 8, local_size_y = 8) in;
//DeepShadow::VolumeSampling::Dec
//DeepShadow::Isosurface::Dec
//DeepShadow::OpacityScale::Dec
//DeepShadow::GradientOpacity::Dec
//DeepShadow::Mask::Dec
//DeepShadow::LabelMap::Dec
//DeepShadow::Transfer2D::Dec
//DeepShadow::EmptySpace::Dec
//DeepShadow::TriangleHierarchy::Dec
//DeepShadow::Bound::Dec
//DeepShadow::Surfaces::Dec
//DeepShadow::Feeler::Dec
//DeepShadow::Hash::Dec
uniform int u_size;
uniform int u_layer;       // first layer of this face's texels
uniform int u_layersPerFace;
uniform int u_face;        // the face's index among its light's faces
uniform int u_perspective;
uniform vec3 u_origin;
uniform vec3 u_forward;
uniform vec3 u_right;
uniform vec3 u_up;
uniform float u_extent;
uniform float u_near;

uniform int u_deferredPass;
layout(std430, binding = 2) buffer DeferredTexels
{
  uint count;
  uint texels[]; // x | y << 16
} u_deferred;

const float NoHit = 3.4028235e38;
ivec2 g_texel;

void deferTexel()
{
  u_deferred.texels[atomicAdd(u_deferred.count, 1u)] = uint(g_texel.x) | (uint(g_texel.y) << 16);
}
//DeepShadow::Build::Dec
#if defined(LIGHT_SPACE_PAGES)
// Resolution-matched maps (Core/Shadows/ResolutionMatched.h): one invocation per texel of a
// page's slot, apron included, the slots' texels one after the other, 64 to a group (a
// slot of 34^2 in groups of 8 x 8 would leave 28 % of the lanes idle); a dispatch covers
// one superpage (one face, one level: u_size is the level's texels per side). g_texel is
// the texel of the level.
layout(std430, binding = 3) readonly buffer Pages
{
  uint pages[]; // (key, slot) per page (deepshadow::EncodePage)
} u_pages;
uniform int u_pageOffset; // the superpage's first page in the list
uniform int u_pageCount;  // its pages
uniform int u_pageSize;
uniform int u_apron;
uniform int u_slotsPerSide;
ivec2 g_store; // the texel's place in the atlas
#elif defined(LIGHT_SPACE_CAMERA)
// The receivers the camera's pixels show, for resolution-matched maps' page requests: the
// ray of every u_downsample-th pixel (deepshadow::Camera::RayThrough) takes a texel's place.
uniform mat4 u_inverseViewProjection;
uniform vec2 u_viewport;
uniform int u_downsample;
uniform ivec2 u_analysisSize;
#endif

// Where a build stores its texel's value (ShadowMapBuild.glsl).
ivec3 lightSpaceOutputTexel()
{
#ifdef LIGHT_SPACE_PAGES
  return ivec3(g_store, 0);
#else
  return ivec3(g_texel, u_layer);
#endif
}
#ifdef LIGHT_SPACE_CLIP
// A clustered face (deepshadow::ClusteredFaces) marches its cluster's box, and of it only its
// cluster's blocks (label u_clipLabel; 0: an unclustered face, every occupied block) and,
// if they are its, the casting surfaces' crossings.
uniform vec3 u_clipLo;
uniform vec3 u_clipHi;
uniform int u_clipLabel;
uniform int u_clipSurfaces;
uniform sampler3D u_clusterLabels; // per block: 0, or 1 + its cluster (R8, nearest)

bool lightSpaceOwnBlock(ivec3 block)
{
  if (u_clipLabel == 0)
  {
    return texelFetch(u_occupancy, block, 0).r != 0.0;
  }
  return int(round(texelFetch(u_clusterLabels, block, 0).r * 255.0)) == u_clipLabel;
}

// The ray's interval in the volume's box within the cluster's box.
vec2 lightSpaceClip(vec3 indexOrigin, vec3 indexDirection)
{
  return boxIntervalOf(indexOrigin, indexDirection, max(u_clipLo, vec3(0.0)), min(u_clipHi, u_dims - 1.0));
}
#endif
//DeepShadow::Surfaces::Visit

void marchTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  //DeepShadow::Surfaces::TexelInit
  // The last sample inside the box (-1: the ray misses it): a skipped run is visited there
  // at the latest.
  int lastInBox = -1;
  if (tEnter < tExit)
  {
    lastInBox = int(floor((tExit - tEnter) / u_feelerStep - 0.5));
    while (lastInBox >= 0 && !(tEnter + (float(lastInBox) + 0.5) * u_feelerStep < tExit))
    {
      --lastInBox;
    }
    while (tEnter + (float(lastInBox + 1) + 0.5) * u_feelerStep < tExit)
    {
      ++lastInBox;
    }
  }
  vec3 indexStep = indexDirection * u_feelerStep;
  //DeepShadow::Bound::TexelInit
  //DeepShadow::Isosurface::TexelInit
  for (int j = 0; j <= lastInBox; ++j)
  {
    float t = tEnter + (float(j) + 0.5) * u_feelerStep;
    vec3 sampleIndex = indexOrigin + t * indexDirection;
    // Samples outside the bound, or in empty blocks, are one skipped run, visited at its end.
    int skip = 0;
    //DeepShadow::Bound::TexelSkip
    //DeepShadow::EmptySpace::TexelSkip
    if (skip > 0)
    {
      int last = min(j + skip - 1, lastInBox);
      float upTo = tEnter + (float(last) + 0.5) * u_feelerStep;
      //DeepShadow::Surfaces::TexelUpTo
      if (!visitSkipped(last, upTo))
      {
        return;
      }
      j = last;
      continue;
    }
    float upTo = t;
    //DeepShadow::Surfaces::TexelUpTo
    float scalar = sampleScalar(sampleIndex);
    //DeepShadow::Components::TexelSample
    //DeepShadow::Isosurface::TexelSample
    //DeepShadow::OpacityScale::TexelSample
    //DeepShadow::GradientOpacity::TexelSample
    //DeepShadow::Mask::TexelSample
    //DeepShadow::LabelMap::TexelSample
    //DeepShadow::Transfer2D::TexelSample
    if (!visitSample(j, t, scalar))
    {
      return;
    }
  }
  float upTo = NoHit;
  //DeepShadow::Surfaces::TexelUpTo
}
//DeepShadow::Build::Texel

void main()
{
#if defined(LIGHT_SPACE_PAGES)
  int slotSize = u_pageSize + 2 * u_apron;
  int texel = int(gl_WorkGroupID.x * 64u + gl_LocalInvocationIndex);
  if (texel >= u_pageCount * slotSize * slotSize)
  {
    return;
  }
  ivec2 local = ivec2(texel % slotSize, (texel / slotSize) % slotSize);
  uint index = uint(u_pageOffset + texel / (slotSize * slotSize));
  uint key = u_pages.pages[2u * index];
  int slot = int(u_pages.pages[2u * index + 1u]);
  g_texel = ivec2(key & 2047u, (key >> 11) & 2047u) * u_pageSize + local - u_apron;
  g_store = ivec2(slot % u_slotsPerSide, slot / u_slotsPerSide) * slotSize + local;
#elif defined(LIGHT_SPACE_CAMERA)
  g_texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(g_texel, u_analysisSize)))
  {
    return;
  }
  vec2 ndc = 2.0 * (vec2(g_texel) + 0.5) * float(u_downsample) / u_viewport - 1.0;
  vec4 nearPoint = u_inverseViewProjection * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = u_inverseViewProjection * vec4(ndc, 1.0, 1.0);
  vec3 cameraOrigin = nearPoint.xyz / nearPoint.w;
  vec3 cameraDirection = normalize(farPoint.xyz / farPoint.w - cameraOrigin);
#else
  if (u_deferredPass != 0)
  {
    uint index = gl_WorkGroupID.x * 64u + gl_LocalInvocationIndex;
    if (index >= u_deferred.count)
    {
      return;
    }
    g_texel = ivec2(u_deferred.texels[index] & 0xffffu, u_deferred.texels[index] >> 16);
  }
  else
  {
    g_texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(g_texel, ivec2(u_size))))
    {
      return;
    }
  }
#endif
  vec3 origin, direction;
#ifdef LIGHT_SPACE_CAMERA
  origin = cameraOrigin;
  direction = cameraDirection;
#else
  vec2 uv = 2.0 * (vec2(g_texel) + 0.5) / float(u_size) - 1.0;
  if (u_perspective != 0)
  {
    direction = normalize(u_forward + uv.x * u_extent * u_right + uv.y * u_extent * u_up);
    origin = u_origin + u_near * direction;
  }
  else
  {
    origin = u_origin + uv.x * u_extent * u_right + uv.y * u_extent * u_up;
    direction = u_forward;
  }
#endif
  vec3 indexOrigin = (u_worldToIndex * vec4(origin, 1.0)).xyz;
  vec3 indexDirection = (u_worldToIndex * vec4(direction, 0.0)).xyz;
#ifdef LIGHT_SPACE_CLIP
  vec2 inside = lightSpaceClip(indexOrigin, indexDirection);
#else
  vec2 inside = boxInterval(indexOrigin, indexDirection);
#endif
  buildTexel(indexOrigin, indexDirection, max(inside.x, 0.0), inside.y);
}
