// Feature TranslucentLayers: depth-keyed fragments composited in depth order with what the
// shader composites itself: the peeled layers of the translucent meshes (Feature Peel) and
// the segments of the other volumes (Feature VolumeSegments), read and sorted front to back.
// The Dec part gets TRANSLUCENT_LAYERS and LOAD_TRANSLUCENT_LAYERS (one LOAD_LAYER(k) per
// layer: GLSL 3.30 indexes sampler arrays by constants only) and SEGMENT_SLICES (segments of
// all the other volumes) from ShaderComposer.cxx.
//@Dec
#if TRANSLUCENT_LAYERS > 0
uniform usampler2D u_layers[TRANSLUCENT_LAYERS];
#endif
#if SEGMENT_SLICES > 0
uniform usampler3D u_segments; // one slice per segment (Rendering/Translucency/VolumeSegments)
#endif
uniform sampler2D u_opaqueColor; // what opaque geometry left (the volume replaces the pixel)
const int FragmentCapacity = TRANSLUCENT_LAYERS + SEGMENT_SLICES;
vec4 layerColor[FragmentCapacity]; // premultiplied
float layerKey[FragmentCapacity];  // window depth; the ray caster turns it into ray t
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

// Layers end at the first empty one (peeling fills them front to back); each segment that
// holds something is sorted in among them.
void loadLayers(ivec2 layerPixel)
{
  LOAD_TRANSLUCENT_LAYERS
#if SEGMENT_SLICES > 0
  for (int s = 0; s < SEGMENT_SLICES; ++s)
  {
    uvec4 texel = texelFetch(u_segments, ivec3(layerPixel, s), 0);
    float z = uintBitsToFloat(texel.r);
    if (z < 1.0)
    {
      int i = layerCount++;
      for (; i > 0 && layerKey[i - 1] > z; --i)
      {
        layerKey[i] = layerKey[i - 1];
        layerColor[i] = layerColor[i - 1];
      }
      layerKey[i] = z;
      layerColor[i] = vec4(uvec4(texel.g, texel.g >> 16, texel.b, texel.b >> 16) & uvec4(65535u)) / 65535.0;
    }
  }
#endif
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
