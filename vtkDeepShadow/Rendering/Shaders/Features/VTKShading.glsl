// Feature VTKShading: VTK's volume shading (deepshadow::VolumeShading, whose paths and quirks
// Core/VolumeShading.h lists; deepshadow::ShadeVolumeSample is the CPU twin), composed only
// for shaded volumes under ShadingModel VTK. VTK_SHADING_PATH is 1 (lone headlight),
// 2 (directional lights) or 3 (positional lights); VTK_SHADING_REFLECTION is 0 for VTK 9.1's
// half vector, 1 for VTK 9.2's reflected light; Gradient's normal matrix is VTK's.
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
#if VTK_SHADING_PATH == 1 && !VTK_SHADING_REFLECTION
  normal = -normal; // VTK 9.1's headlight path compares the inward normal
#endif
  vec3 lastSpecular = vec3(0.0); // path 2: only the last light's specular
  bool undefined = false;        // path 1: VTK takes pow() of a negative N.H
  litPosition = (u_lightingTransform * vec4(position, 1.0)).xyz;
//@ShadowRay
    if (lightPositional(i))
    {
      shadowToLight = towardsLight(i, position, lightDistance); // the shadow ray leaves from the sample itself
    }
//@Halfway
#if VTK_SHADING_PATH == 1
      toLight = normalize(u_worldToShading * toLight);
      halfway = toLight;
#elif VTK_SHADING_REFLECTION
      halfway = normalize(u_eye - litPosition); // not a half vector: the viewer, for R.V below
#elif VTK_SHADING_PATH == 2
      halfway = normalize(toLight + normalize(u_eye - u_mirrorCentre + litPosition));
#else
      halfway = normalize(toLight - normalize(u_eye - litPosition));
#endif
//@Specular
#if VTK_SHADING_REFLECTION
      {
        // R.V, and only where N.L > 0; R reflected with the flipped N.L but for the
        // headlight's (its unflipped one); R.V flipped for positional lights alone.
#if VTK_SHADING_PATH == 1
        float reflectScale = dot(normal, toLight);
#else
        float reflectScale = nDotL;
#endif
        float rDotV = -dot(halfway, normalize(toLight - 2.0 * reflectScale * normal));
#if VTK_SHADING_PATH != 1
        if (u_twoSidedLighting != 0 && lightPositional(i))
        {
          rDotV = abs(rDotV);
        }
#endif
        nDotH = nDotL > 0.0 ? rDotV : 0.0;
      }
#elif VTK_SHADING_PATH == 1
      undefined = undefined || nDotH < 0.0;
#endif
//@Accumulate
#if VTK_SHADING_PATH == 2 && !VTK_SHADING_REFLECTION
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
