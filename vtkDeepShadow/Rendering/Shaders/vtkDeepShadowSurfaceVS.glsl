#version 330 core
// A mesh of vtkDeepShadowPolyDataMapper: points in the actor's coordinates, carried to world
// space (where lights and shadow structures live) and to clip space.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;
uniform mat4 u_modelToWorld;
uniform mat3 u_normalToWorld; // inverse transpose of the model-to-world Jacobian
uniform mat4 u_worldToClip;
out vec3 v_position;
out vec3 v_normal;
out vec4 v_color;
void main()
{
  vec4 world = u_modelToWorld * vec4(a_position, 1.0);
  v_position = world.xyz / world.w;
  v_normal = u_normalToWorld * a_normal;
  v_color = a_color;
  gl_Position = u_worldToClip * world;
}
