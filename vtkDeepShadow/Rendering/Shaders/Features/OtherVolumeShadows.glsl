// Feature OtherVolumeShadows: what the other volumes of the scene cast onto this receiver
// (a volume, or a mesh), multiplied into each light's visibility. vtkDeepShadowPass stores
// their product per light on a grid over the receiver (deepshadow::OtherVolumeShadows; the
// CPU twin is ReferenceRenderer with Scene::OtherVolumeShadowSize > 0).
//@Dec
uniform sampler3D u_otherShadows;   // RGBA16F, one slab per light along z
uniform vec3 u_otherDims;
uniform float u_otherSlabs;
uniform mat4 u_otherWorldToNode;
uniform int u_otherSlab[MaxLights]; // the light's slab, -1: no other volume shadows it
//@Impl
      if (u_otherSlab[i] >= 0)
      {
        visibility *= gridVisibility(u_otherShadows, u_otherWorldToNode, u_otherDims, u_otherSlabs,
          u_otherSlab[i], shadowPosition).rgb;
        shadowed = true;
      }
