// Feature Phong: the diffuse and specular light of one light at a surface-like point of
// normal `normal` (deepshadow::PhongLight and ShadeVolumeSample are the CPU twins); Gradient
// gives volume samples their normal, MeshNormal the points of meshes; VTKShading VTK's half
// vector.
//@Surface
    {
      vec3 halfway = normalize(toLight + toViewer);
      //DeepShadow::VTKShading::Halfway
      float nDotL = dot(normal, toLight);
      float nDotH = dot(normal, halfway);
      if (u_twoSidedLighting != 0)
      {
        nDotL = abs(nDotL);
        nDotH = abs(nDotH);
      }
      //DeepShadow::VTKShading::Specular
      nDotL = max(nDotL, 0.0);
      nDotH = max(nDotH, 0.0);
      float specular = nDotH > 0.0 ? pow(nDotH, material.w) : 0.0;
      specularPart = material.z * specular * u_lightSpecular[i];
      specularLit = nDotH > 0.0;
      contribution = material.y * nDotL * u_lightDiffuse[i] * color + specularPart;
    }
