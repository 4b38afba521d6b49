// Feature MeshNormal: meshes that receive shadows (vtkDeepShadowPolyDataMapper; the hybrid
// part of deepshadow::ReferenceRenderer is the CPU twin). The normal is the interpolated
// point normal; a shadow lookup starts deepshadow::ReceiverOffset towards the light, so that a
// surface that casts does not shadow itself at its own depth (acne).
//@Dec
in vec3 v_normal;
uniform float u_receiverOffset; // world distance at normal incidence
//@Normal
  vec3 normal = normalize(v_normal);
//@ShadowOffset
      {
        // deepshadow::ReceiverOffset: grows towards grazing light, where depths vary fastest.
        float offset = u_receiverOffset / max(abs(dot(normal, toLight)), 0.25);
        shadowPosition += offset * toLight;
        shadowDistance -= offset;
      }
