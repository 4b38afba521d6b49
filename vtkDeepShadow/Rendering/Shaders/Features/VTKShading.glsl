// Feature VTKShading: VTK 9.1's volume shading (deepshadow::VolumeShading, whose paths and
// quirks Core/VolumeShading.h lists; deepshadow::ShadeVolumeSample is the CPU twin), composed
// only for shaded volumes under ShadingModel VTK. VTK_SHADING_PATH is 1 (lone headlight),
// 2 (directional lights) or 3 (positional lights); Gradient's normal matrix is VTK's.
//@Dec
uniform mat3 u_worldToShading; // path 1: world vectors to the volume's dataset space
uniform vec3 u_eye;            // the camera's position
uniform vec3 u_mirrorCentre;   // path 2: twice the first voxel's world position
uniform mat4 u_lightingTransform; // paths 2 and 3: where a sample is lit, from where it is
//@Ambient
#if VTK_SHADING_PATH != 1
  lit = material.x * u_ambientLight; // the lights' ambient colours, not times the colour
#endif
//@Start
#if VTK_SHADING_PATH == 1
  normal = -normal; // VTK's headlight path compares the inward normal
#endif
  vec3 lastSpecular = vec3(0.0); // path 2: only the last light's specular
  bool undefined = false;        // path 1: VTK takes pow() of a negative N.H
  litPosition = (u_lightingTransform * vec4(position, 1.0)).xyz;
//@ShadowRay
    if (u_lightPositional[i] != 0)
    {
      // The shadow ray leaves from the sample itself.
      vec3 fromLight = position - u_lightPosition[i];
      lightDistance = length(fromLight);
      shadowToLight = lightDistance > 0.0 ? -fromLight / lightDistance : vec3(0.0, 0.0, 1.0);
    }
//@Halfway
#if VTK_SHADING_PATH == 1
      toLight = normalize(u_worldToShading * toLight);
      halfway = toLight;
#elif VTK_SHADING_PATH == 2
      halfway = normalize(toLight + normalize(u_eye - u_mirrorCentre + litPosition));
#else
      halfway = normalize(toLight - normalize(u_eye - litPosition));
#endif
//@Specular
#if VTK_SHADING_PATH == 1
      undefined = undefined || nDotH < 0.0;
#endif
//@Accumulate
#if VTK_SHADING_PATH == 2
    if (specularLit)
    {
      lastSpecular = attenuation * specularPart;
    }
    contribution -= specularPart;
#endif
//@Finish
  lit += lastSpecular;
  if (undefined)
  {
    lit = vec3(0.0); // pow's NaN, clamped: black (Mesa; GLSL leaves it undefined)
  }
