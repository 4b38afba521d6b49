// Feature OpaqueDepth: opaque geometry already drawn ends the ray at its depth.
//@Dec
uniform sampler2D u_opaqueDepth; // window depth of the opaque geometry in this viewport
//@Impl
  {
    float depth = texelFetch(u_opaqueDepth, ivec2(pixel), 0).r;
    if (depth < 1.0)
    {
      t1 = min(t1, windowDepthToRayT(depth, ndc, rayOrigin, rayDirection));
    }
  }
