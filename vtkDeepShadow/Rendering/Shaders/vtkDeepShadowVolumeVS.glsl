#version 330 core
// Ray-casting proxy: the volume's box [0, Dims - 1] in voxel-index space. Only its back faces
// are drawn (GL_DEPTH_CLAMP on), so every covered pixel runs the fragment shader once, also
// when the camera is inside the volume.
uniform mat4 u_indexToClip;
layout(location = 0) in vec3 a_corner; // 0 or 1 per axis
uniform vec3 u_boxMax;                 // Dims - 1
void main()
{
  gl_Position = u_indexToClip * vec4(a_corner * u_boxMax, 1.0);
}
