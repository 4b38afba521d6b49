// Feature Isosurface: isosurface blending, as VTK's mapper draws it (deepshadow::IsoCrossings
// in Core/Isosurface.cxx is the CPU twin). Along a ray, a surface where the scalar crosses a
// contour value between two samples: the first sample only finds its interval among the
// values, and one crossing counts per step at most. The transfer table holds uncorrected
// opacity here; its colour and opacity are looked up at the contour crossed. The light's rays
// of every technique (feelers, light-space builds) meet the same crossings, so the surfaces
// are what casts; a surface receives light at the sample before it, on the viewer's side.
//@Dec
const int MaxIsoValues = 16;        // deepshadow::MaxIsoValues
const float IsoNoCrossing = -3.0e38;
uniform float u_isoValues[MaxIsoValues]; // sorted, in the shaders' scalar
uniform int u_isoCount;
uniform float u_isoReceiverOffset; // world distance

// The contour crossed since the previous sample of this ray, or IsoNoCrossing; `interval`
// (values at or below the previous sample; -1 before the first) follows the ray.
float isoNext(inout int interval, float scalar)
{
  if (interval < 0)
  {
    interval = 0;
    while (interval < u_isoCount && u_isoValues[interval] <= scalar)
    {
      ++interval;
    }
    return IsoNoCrossing;
  }
  if (interval > 0 && scalar < u_isoValues[interval - 1])
  {
    --interval;
    return u_isoValues[interval];
  }
  if (interval < u_isoCount && scalar > u_isoValues[interval])
  {
    ++interval;
    return u_isoValues[interval - 1];
  }
  return IsoNoCrossing;
}
//@ShadowOffset
      // deepshadow::IsoReceiverOffset (u_isoReceiverOffset) towards the light.
      shadowPosition += u_isoReceiverOffset * shadowToLight;
      shadowDistance -= u_isoReceiverOffset;
//@Init
  int isoInterval = -1;
  float isoPreviousT = t0;
//@Impl
    receiverT = isoPreviousT;
    isoPreviousT = t;
    scalar = isoNext(isoInterval, scalar);
    if (scalar == IsoNoCrossing)
    {
      continue;
    }
//@FeelerInit
  int isoInterval = -1;
//@FeelerSample
    scalar = isoNext(isoInterval, scalar);
//@FeelerLookup
  if (scalar == IsoNoCrossing)
  {
    return vec4(0.0);
  }
//@TexelInit
  int isoInterval = -1;
//@TexelSample
    scalar = isoNext(isoInterval, scalar);
