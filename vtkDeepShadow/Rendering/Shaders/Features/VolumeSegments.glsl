// Feature VolumeSegments: this volume's march cut, along each view ray, into VOLUME_SEGMENTS
// pieces of equal length between its entry and its exit (or the opaque depth), each
// composited on its own and written, at its opacity-weighted mean depth, as one texel per
// piece (window depth as float bits, premultiplied RGBA as two pairs of 16-bit fixed
// point; depth 1 is empty). The volume that merges the translucent layers merges these too (Features/
// TranslucentLayers.glsl), so volumes interleave along the view ray at the pieces' grain.
// The Dec part gets VOLUME_SEGMENTS, SEGMENT_OUTPUTS and WRITE_VOLUME_SEGMENTS (one output
// per piece) from ShaderComposer.cxx. deepshadow::ReferenceRenderer with
// Scene::VolumeSegments is the CPU twin.
//@Output
#define VOLUME_SEGMENT_OUTPUT
SEGMENT_OUTPUTS
vec4 fragColor; // the march's own result, not written
//@Dec
uniform mat4 u_worldToClip;
vec4 segmentColor[VOLUME_SEGMENTS];   // premultiplied, each piece on its own
float segmentWeightedT[VOLUME_SEGMENTS];
float segmentScale = 0.0;             // pieces per unit of ray t

// Two values in [0, 1] as 16-bit fixed point (GLSL 3.30 has no packUnorm2x16).
uint packPair(vec2 v)
{
  uvec2 q = uvec2(round(clamp(v, 0.0, 1.0) * 65535.0));
  return q.x | (q.y << 16);
}

uvec4 segmentTexel(int s, vec3 rayOrigin, vec3 rayDirection)
{
  if (!(segmentColor[s].a > 0.0))
  {
    return uvec4(floatBitsToUint(1.0), 0u, 0u, 0u);
  }
  float t = segmentWeightedT[s] / segmentColor[s].a;
  vec4 clip = u_worldToClip * vec4(rayOrigin + t * rayDirection, 1.0);
  float depth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 0.99999994); // 1 would read as empty
  return uvec4(floatBitsToUint(depth), packPair(segmentColor[s].rg), packPair(segmentColor[s].ba), 0u);
}
//@Init
  for (int s = 0; s < VOLUME_SEGMENTS; ++s)
  {
    segmentColor[s] = vec4(0.0);
    segmentWeightedT[s] = 0.0;
  }
  segmentScale = float(VOLUME_SEGMENTS) / (t1 - t0);
//@Impl
    {
      int s = clamp(int((t - t0) * segmentScale), 0, VOLUME_SEGMENTS - 1);
      float weight = (1.0 - segmentColor[s].a) * transfer.a;
      segmentWeightedT[s] += weight * t;
      segmentColor[s] += vec4(weight * color, weight);
    }
//@Exit
  WRITE_VOLUME_SEGMENTS
