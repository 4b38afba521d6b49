// Feature DatasetOpacity: opacity integrated per dataset unit under a vtkVolume scaled
// differently along its axes, as VTK's mapper integrates it (it steps and corrects in the
// dataset's units, so its picture is the unscaled volume's, warped). A world step of this ray
// covers |M^-1 d| dataset units; the tables are corrected for the mean scale, so each
// sample's opacity a becomes 1 - (1 - a)^(mean scale |M^-1 d|). The CPU twin is
// deepshadow::ReferenceRenderer::MarchRay (VolumeInstance::WorldToDataset).
//@Dec
uniform mat3 u_worldToDataset; // the vtkVolume's matrix, linear part, undone
uniform float u_datasetScale;  // its mean scale (the cube root of its determinant)
//@Init
  float datasetStretch = u_datasetScale * length(u_worldToDataset * rayDirection);
//@Impl
    transfer.a = 1.0 - pow(max(1.0 - transfer.a, 0.0), datasetStretch);
