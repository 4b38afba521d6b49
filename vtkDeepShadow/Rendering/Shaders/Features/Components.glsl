// Feature Components: volumes of two to four components per voxel (COMPONENT_COUNT), classified
// and combined as VTK's mapper does (COMPONENT_MODE: 0 independent, 1 luminance and opacity,
// 2 RGBA; deepshadow::CombineComponents in Core/Components.h is the CPU twin). Component 0 is
// the volume's own texture and table; components 1.. have their own texture, scalar map and
// table each (over their own range). Every pass that reads the volume reads all components:
// the view ray, the feelers and the light-space builds, so what shows is what casts.
// Independent components that are shaded (COMPONENTS_LIT_APART) are each lit with their own
// gradient and material before they are combined. With COMPONENT_GRADIENT_OPACITY each
// component's opacity is multiplied by its own gradient-opacity function at its own gradient
// before they combine (ComponentSet::GradientFactors), in every pass.
//@Dec
uniform sampler3D u_component1;
#if COMPONENT_COUNT > 2
uniform sampler3D u_component2;
#endif
#if COMPONENT_COUNT > 3
uniform sampler3D u_component3;
#endif
uniform vec2 u_componentScalarMap[4]; // texel -> the shaders' scalar, per component
uniform vec2 u_componentTableMap[4];  // the shaders' scalar -> table coordinate, per component
uniform vec2 u_componentColorMap[4];  // RGBA: the shaders' scalar -> colour (the texture value)
uniform vec4 u_componentWeight;
uniform vec4 u_componentMaterial[4];  // ambient, diffuse, specular, power (shaded components)
vec4 g_componentValues = vec4(0.0);   // the sample's components, where the volume is read
int g_component = 0;                  // the component being lit (its gradient and material)

float sampleComponent(vec3 index, int c)
{
  vec3 coordinate = (index + 0.5) / u_dims;
  if (c == 1)
  {
    return texture(u_component1, coordinate).r * u_componentScalarMap[1].x + u_componentScalarMap[1].y;
  }
#if COMPONENT_COUNT > 2
  if (c == 2)
  {
    return texture(u_component2, coordinate).r * u_componentScalarMap[2].x + u_componentScalarMap[2].y;
  }
#endif
#if COMPONENT_COUNT > 3
  if (c == 3)
  {
    return texture(u_component3, coordinate).r * u_componentScalarMap[3].x + u_componentScalarMap[3].y;
  }
#endif
  return sampleScalar(index);
}

vec4 sampleComponents(vec3 index)
{
  vec4 values = vec4(0.0);
  for (int c = 0; c < COMPONENT_COUNT; ++c)
  {
    values[c] = sampleComponent(index, c);
  }
  return values;
}

#ifdef COMPONENT_GRADIENT_OPACITY
uniform sampler2D u_componentGradientOpacity; // a row per component: its function over magnitude / largest
uniform vec2 u_componentGradientMap;          // magnitude / largest -> table coordinate
uniform vec3 u_componentGradientScale;        // per index axis: mean spacing / spacing
uniform vec4 u_componentGradientUnit;         // per component: data units per shaders' scalar
uniform vec4 u_componentGradientMax;          // per component: its largest magnitude (0: no function)
vec4 g_componentGradientFactors = vec4(1.0);  // the sample's, where a light ray reads the volume
vec3 indexGradient(vec3 index);               // (VolumeSampling, of component g_component)

// Each component's gradient-opacity factor at `index`, for those of opacity above 0 in `alphas`.
vec4 componentGradientFactors(vec3 index, vec4 alphas)
{
  vec4 factors = vec4(1.0);
  for (int c = 0; c < COMPONENT_COUNT; ++c)
  {
    float largest = u_componentGradientMax[c];
    if (largest > 0.0 && alphas[c] > 0.0)
    {
      g_component = c;
      float magnitude = clamp(
        length(indexGradient(index) * u_componentGradientScale) * u_componentGradientUnit[c], 0.0, largest);
      float row = (float(c) + 0.5) / float(COMPONENT_COUNT);
      factors[c] = texture(u_componentGradientOpacity,
        vec2(magnitude / largest * u_componentGradientMap.x + u_componentGradientMap.y, row)).a;
    }
  }
  g_component = 0;
  return factors;
}

vec4[4] withGradientFactors(vec4 colors[4], vec4 factors)
{
  for (int c = 0; c < 4; ++c)
  {
    colors[c].a *= factors[c];
  }
  return colors;
}
#define GRADIENT_FACTORS(COLORS) withGradientFactors(COLORS, g_componentGradientFactors)
#else
#define GRADIENT_FACTORS(COLORS) COLORS
#endif

// Component `c`'s colour and opacity from its table.
vec4 componentLookup(sampler2D table, vec4 values, int c)
{
  return texture(table, vec2(values[c] * u_componentTableMap[c].x + u_componentTableMap[c].y, 0.5));
}

// The sample's component c through table TABLE (the view's or the feelers'): a component
// that does not exist, and its table, is never named.
#define LOOKUP_1(TABLE) componentLookup(TABLE, g_componentValues, 1)
#if COMPONENT_COUNT > 2
#define LOOKUP_2(TABLE) componentLookup(TABLE, g_componentValues, 2)
#else
#define LOOKUP_2(TABLE) vec4(0.0)
#endif
#if COMPONENT_COUNT > 3
#define LOOKUP_3(TABLE) componentLookup(TABLE, g_componentValues, 3)
#else
#define LOOKUP_3(TABLE) vec4(0.0)
#endif

// The sample's colour (not premultiplied) and opacity from each component's.
vec4 combineComponents(vec4 colors[4], vec4 values)
{
#if COMPONENT_MODE == 1
  return vec4(colors[0].rgb, colors[1].a);
#elif COMPONENT_MODE == 2
  vec3 rgb;
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = values[c] * u_componentColorMap[c].x + u_componentColorMap[c].y;
  }
  return vec4(rgb, colors[3].a);
#else
  float total = 0.0;
  for (int c = 0; c < COMPONENT_COUNT; ++c)
  {
    total += colors[c].a * u_componentWeight[c];
  }
  if (!(total > 0.0))
  {
    return vec4(0.0);
  }
  vec3 premultiplied = vec3(0.0);
  float alpha = 0.0;
  for (int c = 0; c < COMPONENT_COUNT; ++c)
  {
    if (u_componentWeight[c] <= 0.0)
    {
      continue;
    }
    premultiplied += colors[c].rgb * colors[c].a * u_componentWeight[c];
    alpha += colors[c].a * colors[c].a / total;
  }
  return alpha > 0.0 ? vec4(premultiplied / alpha, min(alpha, 1.0)) : vec4(0.0);
#endif
}
//@GradientSample
  return sampleComponent(index, g_component);
//@ViewDec
uniform sampler2D u_componentTransfer1;
#if COMPONENT_COUNT > 2
uniform sampler2D u_componentTransfer2;
#endif
#if COMPONENT_COUNT > 3
uniform sampler2D u_componentTransfer3;
#endif
//@Impl
    g_componentValues = sampleComponents(index);
    vec4 componentColors[4] = vec4[4](transfer, LOOKUP_1(u_componentTransfer1), LOOKUP_2(u_componentTransfer2),
      LOOKUP_3(u_componentTransfer3));
#ifdef COMPONENT_GRADIENT_OPACITY
    componentColors = withGradientFactors(componentColors, componentGradientFactors(index,
      vec4(componentColors[0].a, componentColors[1].a, componentColors[2].a, componentColors[3].a)));
#endif
    transfer = combineComponents(componentColors, g_componentValues);
//@Material
  return u_componentMaterial[g_component];
//@LightingDec
#ifdef COMPONENTS_LIT_APART
// Each component lit with its own gradient and material, then combined.
vec3 lightComponents(vec4 colors[4], vec4 values, vec3 index, vec3 position, vec3 toViewer)
{
  for (int c = 0; c < COMPONENT_COUNT; ++c)
  {
    if (colors[c].a > 0.0 && u_componentWeight[c] > 0.0)
    {
      g_component = c;
      colors[c].rgb = lightSample(colors[c].rgb, index, position, toViewer);
    }
  }
  g_component = 0;
  return combineComponents(colors, values).rgb;
}
#endif
//@FeelerDec
uniform sampler2D u_componentFeelerTable1;
#if COMPONENT_COUNT > 2
uniform sampler2D u_componentFeelerTable2;
#endif
#if COMPONENT_COUNT > 3
uniform sampler2D u_componentFeelerTable3;
#endif
//@FeelerLookup
  rgba = combineComponents(GRADIENT_FACTORS(vec4[4](rgba, LOOKUP_1(u_componentFeelerTable1),
    LOOKUP_2(u_componentFeelerTable2), LOOKUP_3(u_componentFeelerTable3))), g_componentValues);
//@FeelerSample
    g_componentValues = sampleComponents(sampleIndex);
#ifdef COMPONENT_GRADIENT_OPACITY
    g_componentGradientFactors = componentGradientFactors(sampleIndex, vec4(1.0));
#endif
//@TexelSample
    g_componentValues = sampleComponents(sampleIndex);
#ifdef COMPONENT_GRADIENT_OPACITY
    g_componentGradientFactors = componentGradientFactors(sampleIndex, vec4(1.0));
#endif
