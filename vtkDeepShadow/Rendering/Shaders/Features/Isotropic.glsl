// Feature Isotropic: light scattered equally in all directions, for volumes that are not
// shaded but receive shadows (the reference's diffuse term without the normal).
//@Surface
    contribution = material.y * u_lightDiffuse[i] * color;
