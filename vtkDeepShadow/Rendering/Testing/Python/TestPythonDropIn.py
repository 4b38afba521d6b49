"""A VTK script that never names vtkDeepShadow draws deep shadows once one line overrides
vtkGPUVolumeRayCastMapper: vtkSmartVolumeMapper makes our mapper, the shadowed rods are
darker than the unshadowed ones, and Restore() gives VTK's mapper back."""
import sys

from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkSmartVolumeMapper
from vtkdeepshadow import vtkDeepShadowVolumeMapperFactory
from DeepShadowPythonTesting import RodsScene, foreground


def smart_rods():
    """The rods scene drawn by a vtkSmartVolumeMapper: the mean of its foreground."""
    scene = RodsScene(size=128)
    smart = vtkSmartVolumeMapper()
    smart.SetInputData(scene.scene.GetVolume())
    scene.volume.SetMapper(smart)
    picture = scene.render()
    mode = smart.GetLastUsedRenderMode()
    return float(picture[foreground(picture)].mean()), mode


failures = []


def check(what, good):
    print(f"{what}: {'ok' if good else 'FAILED'}")
    if not good:
        failures.append(what)


check("before: VTK's mapper", vtkGPUVolumeRayCastMapper().GetClassName() != "vtkDeepShadowVolumeMapper")
check("Override('none')", vtkDeepShadowVolumeMapperFactory.Override("none"))
plain, mode = smart_rods()
check("vtkSmartVolumeMapper drew with its GPU mapper", mode == vtkSmartVolumeMapper.GPURenderMode)
check("Override('dsm')", vtkDeepShadowVolumeMapperFactory.Override("dsm"))
made = vtkGPUVolumeRayCastMapper()
check("New() makes ours with a deep shadow map", made.GetClassName() == "vtkDeepShadowVolumeMapper"
      and made.GetShadowTechnique().GetClassName() == "vtkDeepShadowDeepShadowMapTechnique")
shadowed, mode = smart_rods()
print(f"foreground mean: {shadowed:.1f} shadowed, {plain:.1f} unshadowed")
check("the shadowed rods are darker", shadowed < 0.95 * plain)
vtkDeepShadowVolumeMapperFactory.Restore()
check("Restore(): VTK's mapper again", vtkGPUVolumeRayCastMapper().GetClassName() != "vtkDeepShadowVolumeMapper")
sys.exit(1 if failures else 0)
