// Feature Gradient: the normal of a volume sample from its gradient (deepshadow::VolumeShading::
// Normal is the CPU twin), shaded by Phong. A zero gradient gets ambient only.
//@Dec
// The index gradient to the normal's direction (inward): the world gradient (the transpose of
// the world-to-index Jacobian) under Blinn-Phong, VTK's own matrix under VTKShading.
uniform mat3 u_indexGradientToNormal;
//@Normal
  vec3 gradient = u_indexGradientToNormal * indexGradient(index);
  float gradientLength = length(gradient);
  if (gradientLength <= 0.0)
  {
    return clamp(lit, 0.0, 1.0);
  }
  vec3 normal = -gradient / gradientLength;
