// Feature Projection: the blend modes that project the samples instead of compositing them,
// as VTK's mapper draws them (deepshadow::ProjectionAccumulator in Core/Projection.cxx is the
// CPU twin). Maximum and minimum intensity: the colour and opacity of the extreme scalar;
// average intensity and additive: grey, the mean or the sum of opacity x normalized scalar.
// The transfer table holds uncorrected opacity here (corrected for additive blending, as
// VTK's); no sample is skipped for being clear.
//@Dec
uniform int u_blendMode;          // deepshadow::BlendMode: 1 maximum, 2 minimum, 3 average, 4 additive
uniform vec2 u_normalizeMap;      // the shaders' scalar -> [0, 1] over the data's range
uniform vec2 u_averageRange;      // the scalars average intensity counts, in the shaders' scalar
//@Init
  float projectionExtreme = 0.0;
  float projectionSum = 0.0;
  float projectionCount = 0.0;
//@Impl
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
//@Exit
  if (projectionCount == 0.0)
  {
    discard;
  }
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
