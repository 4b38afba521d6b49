// Feature LabelMap: a label-map mask (vtkGPUVolumeRayCastMapper::SetMaskTypeToLabelMap) as VTK
// 9.1's mapper draws it; deepshadow::LabelMap in Core/Mask.h is the CPU twin. The mask's
// nearest voxel picks a label; a labelled sample takes its label's colour and uncorrected
// opacity from row (label - 1) of u_labelTable at the volume's scalar, mixed with the
// volume's own by the mask blend factor; label 0 keeps the volume's. The view ray, the
// feelers and the light-space builds all read it: what is drawn casts.
//@Dec
uniform sampler3D u_mask;
uniform vec2 u_maskToData;      // texel -> the mask's data value
uniform vec2 u_maskToLabel;     // the mask's data value -> label (floored)
uniform int u_labelCount;       // N: labels 1..N have rows
uniform sampler2D u_labelTable; // row k - 1: label k's colour and opacity (uncorrected)
uniform float u_maskBlendFactor;
uniform float u_labelViewStep;  // the step labels' opacities hold for (the view's, still)
uniform float u_labelUnlitWeight; // 1, or 0 where the view draws the shadow term
int g_label = 0;                // the light's sample at hand's label
vec3 g_labelUnlit = vec3(0.0);  // the view sample's colour added after lighting

int labelAt(vec3 index)
{
  float value = texture(u_mask, (index + 0.5) / u_dims).r * u_maskToData.x + u_maskToData.y;
  return int(clamp(floor(value * u_maskToLabel.x + u_maskToLabel.y), 0.0, float(u_labelCount)));
}

// `volume` (the volume's colour and opacity) where `label` is 0, else the label's, its
// opacity a seen by a step of `stepRatio` view steps as 1 - (1 - a)^stepRatio, mixed with the
// volume's by the blend factor; `unlit`: the part of the colour that is not lit (a label's
// colour where its opacity is 0, as VTK mixes it).
vec4 labelled(vec4 volume, float scalar, int label, float stepRatio, out vec3 unlit)
{
  unlit = vec3(0.0);
  if (label == 0)
  {
    return volume;
  }
  vec4 own = texture(u_labelTable,
    vec2(scalar * u_tableMap.x + u_tableMap.y, (float(label) - 0.5) / float(u_labelCount)));
  own.a = 1.0 - pow(max(1.0 - own.a, 0.0), stepRatio);
  if (u_maskBlendFactor >= 1.0)
  {
    return own;
  }
  vec4 drawn = volume.a > 0.0 ? volume : vec4(0.0);
  if (own.a > 0.0)
  {
    return mix(drawn, own, u_maskBlendFactor);
  }
  unlit = u_maskBlendFactor * own.rgb;
  return (1.0 - u_maskBlendFactor) * drawn;
}
//@Impl
    transfer = labelled(transfer, scalar, labelAt(index), 1.0, g_labelUnlit);
//@Lit
    color += u_labelUnlitWeight * g_labelUnlit;
//@FeelerSample
    g_label = labelAt(sampleIndex);
//@TexelSample
    g_label = labelAt(sampleIndex);
//@FeelerLookup
  {
    vec3 unlit;
    rgba = labelled(rgba, scalar, g_label, u_feelerStep / u_labelViewStep, unlit);
    rgba.rgb += unlit;
  }
