// Feature Feeler: the march from a point towards a light through the volume (the shadow-ray
// technique, per sample or per cache node; deepshadow::FeelerVisibility in Core/Shadows.cxx
// is the CPU twin), and the sample lookups of the light-space builds. Samples sit at
// (j + 0.5) * u_feelerStep from the start; colour and opacity come from u_feelerTable,
// opacity corrected for that step. Opaque: 0 at the first occluder (deepshadow::OccluderTest:
// where the accumulated opacity exceeds the threshold, or the first sample above it);
// translucent: the product of (1 - alpha), or per channel of (1 - alpha (1 - colour)) when
// coloured (feature FeelerColored), stopped once below u_feelerTermination (0: never).
//@Dec
//DeepShadow::FeelerColored::Dec
//DeepShadow::Components::FeelerDec
uniform sampler2D u_feelerTable;   // RGBA table; alpha = opacity corrected for u_feelerStep
uniform float u_feelerStep;        // world units
uniform float u_feelerThreshold;   // accumulated opacity, corrected opacity or normalized scalar
uniform int u_feelerThresholdMode; // deepshadow::ThresholdMode
const int ThresholdAccumulated = 0;
const int ThresholdOpacity = 1;
const int ThresholdScalar = 2;
uniform vec2 u_scalarRange;
uniform float u_feelerTermination; // transmittance at which translucent feelers stop
uniform int u_feelerSkipEmpty;     // may skip empty blocks (see SetFeelerUniforms)

vec4 feelerSample(float scalar)
{
  //DeepShadow::Isosurface::FeelerLookup
  vec4 rgba = texture(u_feelerTable, vec2(scalar * u_tableMap.x + u_tableMap.y, 0.5));
  //DeepShadow::Transfer2D::FeelerLookup
  //DeepShadow::Components::FeelerLookup
  //DeepShadow::LabelMap::FeelerLookup
  //DeepShadow::OpacityScale::FeelerLookup
  return rgba;
}

float feelerAlpha(float scalar)
{
  return feelerSample(scalar).a;
}

// What a sample of colour and opacity `rgba` lets through, and the largest channel of it.
#ifdef FEELER_COLORED
#define FeelerTransmittance vec3
vec3 feelerTransmission(vec4 rgba)
{
  return 1.0 - rgba.a * (1.0 - rgba.rgb);
}
float feelerLargest(vec3 transmittance)
{
  return max(max(transmittance.r, transmittance.g), transmittance.b);
}
#else
#define FeelerTransmittance float
float feelerTransmission(vec4 rgba)
{
  return 1.0 - rgba.a;
}
float feelerLargest(float transmittance)
{
  return transmittance;
}
#endif

// deepshadow::OccluderTest: whether a light ray that has let through `transmittance` so far
// is blocked once a sample or mesh crossing counts that lets through `transmission` (grey)
// and is `above` a per-sample threshold on its own: the accumulated opacity decides in the
// accumulated mode, `above` in the others.
bool occluderCounts(float transmission, bool above, inout float transmittance)
{
  if (u_feelerThresholdMode == ThresholdAccumulated)
  {
    transmittance *= transmission;
    return 1.0 - transmittance > u_feelerThreshold;
  }
  return above;
}

bool feelerOccludes(float scalar, inout float transmittance)
{
  bool above;
  if (u_feelerThresholdMode == ThresholdScalar)
  {
    float width = u_scalarRange.y > u_scalarRange.x ? u_scalarRange.y - u_scalarRange.x : 1.0;
    above = (scalar - u_scalarRange.x) / width > u_feelerThreshold;
  }
  else
  {
    above = feelerAlpha(scalar) > u_feelerThreshold;
  }
  return occluderCounts(1.0 - feelerAlpha(scalar), above, transmittance);
}

// From voxel index `start` along index-space direction `indexDirection` (per world unit), the
// samples at (j + 0.5) * u_feelerStep in [tStart, tEnd) (world distances). `opaque`: binary
// visibility, the ray having let through `occluderTransmittance` before (what meshes let
// through, for the accumulated threshold); else the transmittance.
vec3 feelerVisibility(vec3 start, vec3 indexDirection, float tStart, float tEnd, bool opaque,
  float occluderTransmittance)
{
  FeelerTransmittance transmittance = FeelerTransmittance(1.0);
  vec3 indexStep = indexDirection * u_feelerStep;
  //DeepShadow::Bound::FeelerInit
  //DeepShadow::Isosurface::FeelerInit
  for (int j = tStart > 0.0 ? int(ceil(tStart / u_feelerStep - 0.5)) : 0;; ++j)
  {
    float t = (float(j) + 0.5) * u_feelerStep;
    if (!(t < tEnd))
    {
      break;
    }
    //DeepShadow::Bound::FeelerSkip
    vec3 sampleIndex = start + t * indexDirection;
    //DeepShadow::EmptySpace::FeelerSkip
    float scalar = sampleScalar(sampleIndex);
    //DeepShadow::Components::FeelerSample
    //DeepShadow::Isosurface::FeelerSample
    //DeepShadow::OpacityScale::FeelerSample
    //DeepShadow::GradientOpacity::FeelerSample
    //DeepShadow::Mask::FeelerSample
    //DeepShadow::LabelMap::FeelerSample
    //DeepShadow::Transfer2D::FeelerSample
    if (opaque)
    {
      if (feelerOccludes(scalar, occluderTransmittance))
      {
        return vec3(0.0);
      }
      continue;
    }
    transmittance *= feelerTransmission(feelerSample(scalar));
    if (feelerLargest(transmittance) < u_feelerTermination)
    {
      break;
    }
  }
  return vec3(transmittance);
}

// Visibility of a light from world point `position`: the feeler from there towards it through
// the volume's box (from its entry when the point is outside), up to the light itself, times
// what the casting surfaces in between let through (feature Surfaces).
vec3 feelerTowardsLight(vec3 position, vec3 toLight, float lightDistance, bool opaque)
{
  vec3 start = (u_worldToIndex * vec4(position, 1.0)).xyz;
  vec3 indexDirection = (u_worldToIndex * vec4(toLight, 0.0)).xyz;
  FeelerTransmittance surfaces = FeelerTransmittance(1.0);
  //DeepShadow::Surfaces::Feeler
  vec2 box = boxInterval(start, indexDirection);
  float tEnd = min(box.y, lightDistance);
  if (opaque)
  {
    // Binary: meshes are part of the test (accumulated) or stopped it already.
    return feelerVisibility(start, indexDirection, box.x, tEnd, true, feelerLargest(surfaces));
  }
  return vec3(surfaces) * feelerVisibility(start, indexDirection, box.x, tEnd, false, 1.0);
}
