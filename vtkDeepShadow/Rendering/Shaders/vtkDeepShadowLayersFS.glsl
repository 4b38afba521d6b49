#version 330 core
// The peeled translucent layers over pixels that no ray caster composites them into
// (Rendering/Translucency/TranslucentLayers.cxx). Output is premultiplied.
layout(location = 0) out vec4 fragColor;
in vec2 texCoord;        // VTK's full-screen quad: [0, 1] over the viewport
uniform vec4 u_viewport; // x, y, width, height in window pixels

//DeepShadow::TranslucentLayers::Dec

void main()
{
  loadLayers(ivec2(texCoord * u_viewport.zw)); // pixel centres: (i + 0.5) / width
  vec4 accumulated = vec4(0.0);
  compositeLayersBefore(2.0, accumulated); // window depths are at most 1
  if (accumulated.a <= 0.0)
  {
    discard;
  }
  fragColor = accumulated;
}
