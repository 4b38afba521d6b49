// Feature MeshNormal: meshes that receive shadows (vtkDeepShadowPolyDataMapper; the hybrid
// part of deepshadow::ReferenceRenderer is the CPU twin). The normal is the interpolated
// point normal; a shadow lookup starts deepshadow::ReceiverOffset towards the light, so that a
// surface that casts does not shadow itself at its own depth (acne).
//@Dec
in vec3 v_normal;
// A mesh's normal faces the viewer (flipped on back faces under two-sided lighting), and
// Phong lights it one-sided, as VTK's surfaces are: |N.L| would light a sphere's far side.
#define FACING_NORMAL
uniform int u_loneHeadlight; // deepshadow::Light::LoneHeadlight: specular (N.L)^p
uniform vec3 u_specularColor; // the property's: the highlights' colour
uniform float u_receiverOffset; // world distance at normal incidence
// The triangle's own plane (its shading normal may be smoothed across edges): shadow lookups
// compare neighbouring texels there (deepshadow::SurfaceSet::FaceNormal). Derivatives are
// taken in main(), in uniform control flow; zero where the triangle is seen edge-on.
vec3 g_faceNormal;
//@Face
  {
    vec3 across = cross(dFdx(v_position), dFdy(v_position));
    g_faceNormal = dot(across, across) > 0.0 ? normalize(across) : vec3(0.0);
  }
//@Normal
  vec3 normal = normalize(v_normal);
  if (u_twoSidedLighting != 0 && !gl_FrontFacing)
  {
    normal = -normal;
  }
//@ShadowOffset
      {
        // deepshadow::ReceiverOffset: grows towards grazing light, where depths vary fastest.
        float offset = u_receiverOffset / max(abs(dot(normal, shadowToLight)), 0.25);
        shadowPosition += offset * shadowToLight;
        shadowDistance -= offset;
        shadowNormal = g_faceNormal;
      }
