// Feature Peel: the mesh pass draws one layer of depth peeling (Rendering/Translucency).
// Each layer keeps, per pixel, the nearest fragment behind the previous layer (the depth test
// does "nearest"; the opaque depth was copied into the depth buffer), as its window depth
// (exact float bits) and its premultiplied colour (8 bits a channel).
//@Dec
layout(location = 1) out uvec2 peelTexel;
uniform usampler2D u_peelPrevious; // the previous layer (see PackLayerTexel)
uniform int u_peelHasPrevious;
//@Init
  if (u_peelHasPrevious != 0 &&
    gl_FragCoord.z <= uintBitsToFloat(texelFetch(u_peelPrevious, ivec2(gl_FragCoord.xy), 0).r))
  {
    discard; // already in an earlier layer
  }
//@Exit
  {
    uvec4 bytes = uvec4(round(clamp(fragColor, 0.0, 1.0) * 255.0));
    peelTexel = uvec2(floatBitsToUint(gl_FragCoord.z),
      bytes.r | (bytes.g << 8) | (bytes.b << 16) | (bytes.a << 24));
  }
