// Feature UserShader: the fragment code of a volume's vtkShaderProperty (Volume/
// UserShaderCode), run where VTK 9.1's mapper runs it, with VTK's names for what it reads
// and writes. The user's code is appended to the parts Dec, Init, Impl, Exit and Output.
//@Dec
vec4 g_fragColor = vec4(0.0); // composited so far (premultiplied)
vec4 g_srcColor = vec4(0.0);  // the sample composited last (premultiplied; 0: none)
vec3 g_dataPos;               // the sample's texture coordinate (texel centres)
vec3 g_dirStep;               // one step along the ray in texture coordinates
bool g_skip = false;          // set at a sample: it is not composited
bool g_exit = false;          // set at a sample: the march ends
uniform mat4 in_projectionMatrix;
uniform mat4 in_modelViewMatrix;
uniform mat4 in_inverseModelViewMatrix;
uniform mat4 in_volumeMatrix[1];
uniform mat4 in_inverseVolumeMatrix[1];
uniform mat4 in_textureDatasetMatrix[1]; // as VTK's: texture coordinates to dataset
uniform mat4 in_inverseTextureDatasetMatrix[1];
uniform vec3 in_cameraPos;
uniform vec3 u_textureSize; // the volume's points per axis (texels)
#define fragOutput0 fragColor
//@Init
  g_dataPos = (indexOrigin + (t0 + offset * u_step) * indexDirection + 0.5) / u_textureSize;
  g_dirStep = u_step * indexDirection / u_textureSize;
//@Impl
    g_dataPos = (index + 0.5) / u_textureSize;
    g_fragColor = accumulated;
//@ImplEnd
    if (g_exit)
    {
      break;
    }
    accumulated = g_fragColor;
    bool userSkip = g_skip;
    g_srcColor = vec4(0.0);
//@Sample
    if (userSkip)
    {
      continue;
    }
    g_srcColor = vec4(color * transfer.a, transfer.a);
//@Exit
  g_fragColor = accumulated;
//@ExitEnd
  accumulated = g_fragColor;
//@Output
