// Feature Phong: the diffuse and specular light of one light at a surface-like point of
// normal `normal` (deepshadow::SurfaceLight and ShadeVolumeSample are the CPU twins); Gradient
// gives volume samples their normal, MeshNormal the points of meshes; VTKShading VTK's half
// vector.
//@Surface
    {
#ifdef FACING_NORMAL
      // A mesh (deepshadow::SurfaceLight): VTK's polygon mapper's Phong reflection, one-sided.
      float nDotL = max(dot(normal, toLight), 0.0);
      float nDotH = u_loneHeadlight != 0 ? nDotL
                  : nDotL > 0.0 ? max(dot(reflect(-toLight, normal), toViewer), 0.0) : 0.0;
      vec3 highlight = u_specularColor;
#else
      vec3 highlight = vec3(1.0); // volumes: VTK's volume mapper has no specular colour
      vec3 halfway = normalize(toLight + toViewer);
      //DeepShadow::VTKShading::Halfway
      float nDotL = dot(normal, toLight);
      float nDotH = dot(normal, halfway);
      if (u_twoSidedLighting != 0) // a volume's gradient has no side (VTK's volume shading)
      {
        nDotL = abs(nDotL);
        nDotH = abs(nDotH);
      }
      //DeepShadow::VTKShading::Specular
      nDotL = max(nDotL, 0.0);
      nDotH = max(nDotH, 0.0);
#endif
      float specular = nDotH > 0.0 ? pow(nDotH, material.w) : 0.0;
      specularPart = material.z * specular * u_lightSpecular[i] * highlight;
      specularLit = nDotH > 0.0;
      contribution = material.y * nDotL * u_lightDiffuse[i] * color + specularPart;
    }
