// Feature Gradient: Phong shading of the gradient normal (deepshadow::PhongLight and
// deepshadow::VolumeGrid::WorldGradient are the CPU twins). A zero gradient gets ambient only.
//@Dec
uniform mat3 u_indexGradientToWorld; // transpose of the world-to-index Jacobian

vec3 worldGradient(vec3 index)
{
  vec3 g;
  g.x = sampleScalar(index + vec3(1.0, 0.0, 0.0)) - sampleScalar(index - vec3(1.0, 0.0, 0.0));
  g.y = sampleScalar(index + vec3(0.0, 1.0, 0.0)) - sampleScalar(index - vec3(0.0, 1.0, 0.0));
  g.z = sampleScalar(index + vec3(0.0, 0.0, 1.0)) - sampleScalar(index - vec3(0.0, 0.0, 1.0));
  return u_indexGradientToWorld * (0.5 * g);
}
//@Normal
  vec3 gradient = worldGradient(index);
  float gradientLength = length(gradient);
  if (gradientLength <= 0.0)
  {
    return clamp(lit, 0.0, 1.0);
  }
  vec3 normal = -gradient / gradientLength;
//@Surface
    {
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
      contribution = u_material.y * nDotL * u_lightDiffuse[i] * color +
        u_material.z * specular * u_lightSpecular[i];
    }
