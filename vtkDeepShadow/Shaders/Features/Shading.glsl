// Feature Shading: Phong shading of the gradient normal with the renderer's lights, in world
// space (deepshadow::PhongLight, deepshadow::Light::At in Core is the CPU twin).
//@Dec
const int MaxLights = 8;
uniform int u_lightCount;
uniform int u_lightPositional[MaxLights];
uniform vec3 u_lightPosition[MaxLights];   // positional lights
uniform vec3 u_lightDirection[MaxLights];  // unit, towards the light (directional) or the
                                           // spot axis from the light (positional)
uniform vec3 u_lightDiffuse[MaxLights];    // colour x intensity
uniform vec3 u_lightSpecular[MaxLights];
uniform vec3 u_lightAttenuation[MaxLights];
uniform float u_lightConeCos[MaxLights];   // cos(cone angle); < -1 means no cone
uniform float u_lightExponent[MaxLights];
uniform vec3 u_ambientLight;
uniform vec4 u_material;                   // ambient, diffuse, specular, specular power
uniform int u_twoSidedLighting;
uniform mat3 u_indexGradientToWorld;       // transpose of the world-to-index Jacobian

vec3 worldGradient(vec3 index)
{
  vec3 g;
  g.x = sampleScalar(index + vec3(1.0, 0.0, 0.0)) - sampleScalar(index - vec3(1.0, 0.0, 0.0));
  g.y = sampleScalar(index + vec3(0.0, 1.0, 0.0)) - sampleScalar(index - vec3(0.0, 1.0, 0.0));
  g.z = sampleScalar(index + vec3(0.0, 0.0, 1.0)) - sampleScalar(index - vec3(0.0, 0.0, 1.0));
  return u_indexGradientToWorld * (0.5 * g);
}

vec3 shade(vec3 color, vec3 index, vec3 position, vec3 toViewer)
{
  vec3 gradient = worldGradient(index);
  float gradientLength = length(gradient);
  vec3 lit = u_material.x * color * u_ambientLight;
  if (gradientLength <= 0.0)
  {
    return clamp(lit, 0.0, 1.0);
  }
  vec3 normal = -gradient / gradientLength;
  for (int i = 0; i < u_lightCount; ++i)
  {
    vec3 toLight = u_lightDirection[i];
    float attenuation = 1.0;
    if (u_lightPositional[i] != 0)
    {
      vec3 fromLight = position - u_lightPosition[i];
      float distance = length(fromLight);
      toLight = distance > 0.0 ? -fromLight / distance : vec3(0.0, 0.0, 1.0);
      attenuation = 1.0 / (u_lightAttenuation[i].x + u_lightAttenuation[i].y * distance +
                            u_lightAttenuation[i].z * distance * distance);
      if (u_lightConeCos[i] >= -1.0)
      {
        float coneDot = dot(-toLight, u_lightDirection[i]);
        attenuation = coneDot >= u_lightConeCos[i] ? attenuation * pow(coneDot, u_lightExponent[i]) : 0.0;
      }
    }
    //DeepShadow::Shadow::Impl
    vec3 halfway = normalize(toLight + toViewer);
    float nDotL = dot(normal, toLight);
    float nDotH = dot(normal, halfway);
    if (u_twoSidedLighting != 0)
    {
      nDotL = abs(nDotL);
      nDotH = abs(nDotH);
    }
    nDotL = max(nDotL, 0.0);
    nDotH = max(nDotH, 0.0);
    float specular = nDotH > 0.0 ? pow(nDotH, u_material.w) : 0.0;
    lit += attenuation * (u_material.y * nDotL * u_lightDiffuse[i] * color +
                          u_material.z * specular * u_lightSpecular[i]);
  }
  return clamp(lit, 0.0, 1.0);
}
//@Impl
    color = shade(color, index, rayOrigin + t * rayDirection, -rayDirection);
