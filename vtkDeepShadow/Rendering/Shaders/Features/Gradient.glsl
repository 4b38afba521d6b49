// Feature Gradient: the normal of a volume sample from its gradient (deepshadow::VolumeGrid::
// WorldGradient is the CPU twin), shaded by Phong. A zero gradient gets ambient only.
//@Dec
uniform mat3 u_indexGradientToWorld; // transpose of the world-to-index Jacobian

vec3 worldGradient(vec3 index)
{
  return u_indexGradientToWorld * indexGradient(index);
}
//@Normal
  vec3 gradient = worldGradient(index);
  float gradientLength = length(gradient);
  if (gradientLength <= 0.0)
  {
    return clamp(lit, 0.0, 1.0);
  }
  vec3 normal = -gradient / gradientLength;
