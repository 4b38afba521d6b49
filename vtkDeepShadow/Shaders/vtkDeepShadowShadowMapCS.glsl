#version 430 core
// Build pass of "shadowmap": for each texel of one face, the depth along the texel's ray of
// the first sample above the threshold (MapShadow::FirstHit in Core/Shadows.cxx is the CPU
// twin); rays that find none store the largest float.
layout(local_size_x = 8, local_size_y = 8) in;
//DeepShadow::VolumeSampling::Dec
//DeepShadow::EmptySpace::Dec
//DeepShadow::Feeler::Dec
layout(r32f, binding = 0) uniform writeonly image2DArray u_output;
uniform int u_size;
uniform int u_layer;
uniform int u_perspective;
uniform vec3 u_origin;
uniform vec3 u_forward;
uniform vec3 u_right;
uniform vec3 u_up;
uniform float u_extent;

const float NoHit = 3.4028235e38;

void main()
{
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, ivec2(u_size))))
  {
    return;
  }
  vec2 uv = 2.0 * (vec2(texel) + 0.5) / float(u_size) - 1.0;
  vec3 origin = u_origin;
  vec3 direction = u_forward;
  if (u_perspective != 0)
  {
    direction = normalize(u_forward + uv.x * u_extent * u_right + uv.y * u_extent * u_up);
  }
  else
  {
    origin = u_origin + uv.x * u_extent * u_right + uv.y * u_extent * u_up;
  }
  vec3 indexOrigin = (u_worldToIndex * vec4(origin, 1.0)).xyz;
  vec3 indexDirection = (u_worldToIndex * vec4(direction, 0.0)).xyz;
  vec2 inside = boxInterval(indexOrigin, indexDirection);
  float tEnter = max(inside.x, 0.0);
  float tExit = inside.y;

  float depth = NoHit;
  vec3 indexStep = indexDirection * u_feelerStep;
  for (int j = 0; tEnter < tExit; ++j)
  {
    float t = tEnter + (float(j) + 0.5) * u_feelerStep;
    if (!(t < tExit))
    {
      break;
    }
    vec3 sampleIndex = indexOrigin + t * indexDirection;
    //DeepShadow::EmptySpace::FeelerSkip
    if (feelerAbove(sampleScalar(sampleIndex)))
    {
      depth = t;
      break;
    }
  }
  imageStore(u_output, ivec3(texel, u_layer), vec4(depth));
}
