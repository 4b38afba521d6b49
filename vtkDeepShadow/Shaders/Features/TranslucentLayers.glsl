// Feature TranslucentLayers: the peeled layers of the translucent meshes (Feature Peel),
// read front to back and composited in depth order with what the shader composites itself.
// The Dec part gets TRANSLUCENT_LAYERS and LOAD_TRANSLUCENT_LAYERS (one LOAD_LAYER(k) per
// layer: GLSL 3.30 indexes sampler arrays by constants only) from TranslucentLayers.cxx.
//@Dec
uniform usampler2D u_layers[TRANSLUCENT_LAYERS];
uniform sampler2D u_opaqueColor; // what opaque geometry left (the volume replaces the pixel)
vec4 layerColor[TRANSLUCENT_LAYERS]; // premultiplied
float layerKey[TRANSLUCENT_LAYERS];  // window depth; the ray caster turns it into ray t
int layerCount = 0;
int nextLayer = 0;

#define LOAD_LAYER(k)                                                                       \
  {                                                                                         \
    uvec2 texel = texelFetch(u_layers[k], layerPixel, 0).rg;                                \
    float z = uintBitsToFloat(texel.r);                                                     \
    if (layerCount == k && z < 1.0)                                                         \
    {                                                                                       \
      layerKey[k] = z;                                                                      \
      layerColor[k] = vec4(uvec4(texel.g, texel.g >> 8, texel.g >> 16, texel.g >> 24) &     \
                        uvec4(255u)) / 255.0;                                               \
      layerCount = k + 1;                                                                   \
    }                                                                                       \
  }

// Layers end at the first empty one (peeling fills them front to back).
void loadLayers(ivec2 layerPixel)
{
  LOAD_TRANSLUCENT_LAYERS
}

// Composites, "over" what is in front, every layer whose key is below `key`.
void compositeLayersBefore(float key, inout vec4 accumulated)
{
  for (; nextLayer < layerCount && layerKey[nextLayer] < key; ++nextLayer)
  {
    accumulated += (1.0 - accumulated.a) * layerColor[nextLayer];
  }
}
//@Init
  loadLayers(ivec2(pixel));
  for (int i = 0; i < layerCount; ++i)
  {
    layerKey[i] = windowDepthToRayT(layerKey[i], ndc, rayOrigin, rayDirection);
  }
//@Miss
  {
    // No sample on this ray: the layers over the opaque image.
    vec4 layersOnly = vec4(0.0);
    compositeLayersBefore(3.0e38, layersOnly);
    fragColor = layersOnly + (1.0 - layersOnly.a) * texelFetch(u_opaqueColor, ivec2(pixel), 0);
    return;
  }
//@Impl
    compositeLayersBefore(t, accumulated);
//@Exit
  // The layers behind the last sample, then the opaque image: the pixel is replaced.
  compositeLayersBefore(3.0e38, accumulated);
  accumulated += (1.0 - accumulated.a) * texelFetch(u_opaqueColor, ivec2(pixel), 0);
