// Feature Projection: the blend modes that project the samples instead of compositing them,
// as VTK's mapper draws them (deepshadow::ProjectionAccumulator and ComponentProjection in
// Core/Projection.h are the CPU twins). Maximum and minimum intensity: the colour and opacity
// of the extreme scalar; average intensity and additive: grey, the mean or the sum of
// opacity x normalized scalar. Several components (with feature Components): independent
// ones each keep their own extreme or sum, dependent ones the sample of extreme opacity
// component. The transfer tables hold uncorrected opacity here (corrected for additive
// blending, as VTK's); no sample is skipped for being clear.
//@Dec
uniform int u_blendMode;          // deepshadow::BlendMode: 1 maximum, 2 minimum, 3 average, 4 additive
uniform vec2 u_normalizeMap;      // the shaders' scalar -> [0, 1] over the data's range
uniform vec2 u_averageRange;      // the scalars average intensity counts, in the shaders' scalar
#ifdef COMPONENT_COUNT
uniform vec2 u_componentNormalizeMap[4]; // the same, per component (its scalar, its range)
uniform vec2 u_componentAverageRange[4];

// Each component's colour and opacity at `values`, from the view's tables.
void projectionLookups(vec4 values, out vec4 colors[4])
{
  g_componentValues = values;
  colors = vec4[4](texture(u_transfer, vec2(values[0] * u_tableMap.x + u_tableMap.y, 0.5)),
    LOOKUP_1(u_componentTransfer1), LOOKUP_2(u_componentTransfer2), LOOKUP_3(u_componentTransfer3));
}

bool projectionCounts(vec4 values, int c)
{
  return u_blendMode == 4 || (values[c] >= u_componentAverageRange[c].x && values[c] <= u_componentAverageRange[c].y);
}
#endif
//@Init
  // VTK's extremes and averages sample from the ray's entry (measured on VTK's wavelet: MIP
  // at steps of 0.3, 0.5 and 1 voxel 0.004-0.012 against VTK from there, 0.029-0.056 from
  // half a step in); jittered offsets stay uniform. Additive sums (0.014 against VTK from
  // the midpoint, 0.021 from the entry) and composite keep the midpoint.
  if (u_blendMode != 4)
  {
    offset = fract(offset + 0.5);
  }
  float projectionExtreme = 0.0;
  float projectionSum = 0.0;
  float projectionCount = 0.0;
#ifdef COMPONENT_COUNT
  vec4 projectionExtremes = vec4(0.0); // independent: each component's; dependent: the sample's
  vec4 projectionSums = vec4(0.0);
  vec4 projectionCounted = vec4(0.0);
#endif
//@Impl
#ifdef COMPONENT_COUNT
    {
      vec4 values = sampleComponents(index);
      bool first = projectionCount == 0.0;
      if (u_blendMode <= 2)
      {
        bool maximum = u_blendMode == 1;
#if COMPONENT_MODE == 0
        projectionExtremes = first ? values : (maximum ? max(projectionExtremes, values) : min(projectionExtremes, values));
#else
        float key = values[COMPONENT_COUNT - 1];
        float kept = projectionExtremes[COMPONENT_COUNT - 1];
        if (first || (maximum ? key > kept : key < kept))
        {
          projectionExtremes = values;
        }
#endif
        projectionCount += 1.0;
      }
      else
      {
        vec4 colors[4];
        projectionLookups(values, colors);
#if COMPONENT_MODE == 0
        for (int c = 0; c < COMPONENT_COUNT; ++c)
        {
          if (projectionCounts(values, c))
          {
            projectionSums[c] += colors[c].a * (values[c] * u_componentNormalizeMap[c].x + u_componentNormalizeMap[c].y);
            projectionCounted[c] += 1.0;
            projectionCount += 1.0;
          }
        }
#else
        if (projectionCounts(values, 0))
        {
          projectionSums[0] += combineComponents(colors, values).a * (values[0] * u_normalizeMap.x + u_normalizeMap.y);
          projectionCounted[0] += 1.0;
          projectionCount += 1.0;
        }
#endif
      }
      continue;
    }
#else
    {
      bool first = projectionCount == 0.0;
      if (u_blendMode == 1)
      {
        projectionExtreme = first ? scalar : max(projectionExtreme, scalar);
        projectionCount += 1.0;
      }
      else if (u_blendMode == 2)
      {
        projectionExtreme = first ? scalar : min(projectionExtreme, scalar);
        projectionCount += 1.0;
      }
      else if (u_blendMode == 4 || (scalar >= u_averageRange.x && scalar <= u_averageRange.y))
      {
        // The table only here: the extremes look it up once, at the end.
        float opacity = texture(u_transfer, vec2(scalar * u_tableMap.x + u_tableMap.y, 0.5)).a;
        projectionSum += opacity * (scalar * u_normalizeMap.x + u_normalizeMap.y);
        projectionCount += 1.0;
      }
      continue;
    }
#endif
//@Exit
  // A ray that counted nothing (masked, outside the bound or the average's range) is not
  // drawn, but additive's sum of nothing is opaque black, as VTK's mapper draws it.
  if (projectionCount == 0.0 && u_blendMode != 4)
  {
    discard;
  }
#ifdef COMPONENT_COUNT
  if (u_blendMode <= 2)
  {
    vec4 colors[4];
    projectionLookups(projectionExtremes, colors);
#if COMPONENT_MODE == 0
    // Summed with every weight (VTK's), kept within what a pixel holds.
    vec4 sum = vec4(0.0);
    for (int c = 0; c < COMPONENT_COUNT; ++c)
    {
      sum += u_componentWeight[c] * colors[c].a * vec4(colors[c].rgb, 1.0);
    }
    accumulated = clamp(sum, 0.0, 1.0);
#else
    vec4 extreme = combineComponents(colors, projectionExtremes);
    accumulated = vec4(extreme.rgb * extreme.a, extreme.a);
#endif
  }
  else
  {
    float grey = 0.0;
    for (int c = 0; c < COMPONENT_COUNT; ++c)
    {
      if (projectionCounted[c] > 0.0)
      {
        float weight = COMPONENT_MODE == 0 ? u_componentWeight[c] : 1.0;
        grey += weight * (u_blendMode == 3 ? projectionSums[c] / projectionCounted[c] : projectionSums[c]);
      }
    }
    accumulated = vec4(vec3(clamp(grey, 0.0, 1.0)), 1.0);
  }
#else
  if (u_blendMode <= 2)
  {
    vec4 extreme = texture(u_transfer, vec2(projectionExtreme * u_tableMap.x + u_tableMap.y, 0.5));
    accumulated = vec4(extreme.rgb * extreme.a, extreme.a);
  }
  else
  {
    float grey = clamp(u_blendMode == 3 ? projectionSum / projectionCount : projectionSum, 0.0, 1.0);
    accumulated = vec4(vec3(grey), 1.0);
  }
#endif
