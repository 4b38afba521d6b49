// Feature VolumeSampling: the volume's scalars at a continuous voxel index, shared by the ray
// caster and the shadow build passes (deepshadow::VolumeGrid::Sample is the CPU twin).
//@Dec
uniform sampler3D u_volume;  // scalars, in [0, 1] (8 and 16 bit formats, float data normalized)
uniform vec2 u_scalarMap;    // scalar = texel * u_scalarMap.x + u_scalarMap.y
uniform vec2 u_tableMap;     // table coordinate = scalar * u_tableMap.x + u_tableMap.y
// (deepshadow::ShadowContext: for float data the shaders' scalar is the normalized one.)
uniform vec3 u_dims;
uniform mat4 u_worldToIndex;

float sampleScalar(vec3 index)
{
  return texture(u_volume, (index + 0.5) / u_dims).r * u_scalarMap.x + u_scalarMap.y;
}

//DeepShadow::Components::Dec

// The value gradients are taken of: the scalar, or the component being lit.
float gradientSample(vec3 index)
{
  //DeepShadow::Components::GradientSample
  return sampleScalar(index);
}

// Half the central differences over +-u_gradientReach voxels, for shading and gradient
// opacity (deepshadow::VolumeGrid::IndexGradient; 2 on a grid resampled from cells).
uniform float u_gradientReach;
vec3 indexGradient(vec3 index)
{
  float r = u_gradientReach;
  vec3 g;
  g.x = gradientSample(index + vec3(r, 0.0, 0.0)) - gradientSample(index - vec3(r, 0.0, 0.0));
  g.y = gradientSample(index + vec3(0.0, r, 0.0)) - gradientSample(index - vec3(0.0, r, 0.0));
  g.z = gradientSample(index + vec3(0.0, 0.0, r)) - gradientSample(index - vec3(0.0, 0.0, r));
  return 0.5 * g;
}

// Parametric interval of the ray index + t * direction inside the box [lo, hi] (boxInterval:
// [0, Dims - 1]; deepshadow::IntersectBox); empty when !(entry < exit).
vec2 boxIntervalOf(vec3 index, vec3 direction, vec3 lo, vec3 hi)
{
  vec3 inverseDirection = 1.0 / direction;
  vec3 tA = (lo - index) * inverseDirection;
  vec3 tB = (hi - index) * inverseDirection;
  vec3 tLow = min(tA, tB);
  vec3 tHigh = max(tA, tB);
  // An axis the direction is parallel to (1/0: a point on its face gives 0 * inf = NaN)
  // constrains nothing inside its slab and empties the interval outside, as
  // deepshadow::IntersectBox does. mix() with a bvec selects, so no NaN leaks through.
  bvec3 parallel = equal(direction, vec3(0.0));
  bvec3 inside = bvec3(vec3(greaterThanEqual(index, lo)) * vec3(lessThanEqual(index, hi)));
  tLow = mix(tLow, mix(vec3(3.0e38), vec3(-3.0e38), inside), parallel);
  tHigh = mix(tHigh, mix(vec3(-3.0e38), vec3(3.0e38), inside), parallel);
  return vec2(max(max(tLow.x, tLow.y), tLow.z), min(min(tHigh.x, tHigh.y), tHigh.z));
}

vec2 boxInterval(vec3 index, vec3 direction)
{
  return boxIntervalOf(index, direction, vec3(0.0), u_dims - 1.0);
}

float boxExit(vec3 index, vec3 direction)
{
  return boxInterval(index, direction).y;
}
