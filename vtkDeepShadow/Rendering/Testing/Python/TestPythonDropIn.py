"""A VTK script that never names vtkDeepShadow draws deep shadows once one line overrides
vtkGPUVolumeRayCastMapper: vtkSmartVolumeMapper and vtkMultiBlockVolumeMapper make our
mapper, the shadowed rods are darker than the unshadowed ones, a cell array chosen by name
(as ParaView chooses arrays) draws the same rods, and Restore() gives VTK's mapper back."""
import sys

from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkMultiBlockDataSet
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkMultiBlockVolumeMapper, vtkSmartVolumeMapper
from vtkdeepshadow import vtkDeepShadowVolumeMapperFactory
from DeepShadowPythonTesting import RodsScene, foreground


def as_named_cells(points):
    """`points`' scalars as the cell array 'density' of a grid one point larger (each cell
    centred on its point), with an array of zeros as the active cell scalars."""
    cells = vtkImageData()
    cells.SetDimensions([n + 1 for n in points.GetDimensions()])
    cells.SetSpacing(points.GetSpacing())
    cells.SetOrigin([o - 0.5 * s for o, s in zip(points.GetOrigin(), points.GetSpacing())])
    density = points.GetPointData().GetScalars().NewInstance()
    density.DeepCopy(points.GetPointData().GetScalars())
    density.SetName("density")
    zeros = density.NewInstance()
    zeros.SetNumberOfTuples(density.GetNumberOfTuples())
    zeros.Fill(0)
    zeros.SetName("zeros")
    cells.GetCellData().SetScalars(zeros)
    cells.GetCellData().AddArray(density)
    return cells


def smart_rods(named_cells=False):
    """The rods scene drawn by a vtkSmartVolumeMapper: the mean of its foreground."""
    scene = RodsScene(size=128)
    smart = vtkSmartVolumeMapper()
    if named_cells:
        smart.SetInputData(as_named_cells(scene.scene.GetVolume()))
        smart.SetScalarModeToUseCellFieldData()
        smart.SelectScalarArray("density")
    else:
        smart.SetInputData(scene.scene.GetVolume())
    scene.volume.SetMapper(smart)
    picture = scene.render()
    mode = smart.GetLastUsedRenderMode()
    return float(picture[foreground(picture)].mean()), mode


def multiblock_rods():
    """The rods as the one block of a vtkMultiBlockVolumeMapper: the mean of its foreground."""
    scene = RodsScene(size=128)
    blocks = vtkMultiBlockDataSet()
    blocks.SetBlock(0, scene.scene.GetVolume())
    mapper = vtkMultiBlockVolumeMapper()
    mapper.SetInputDataObject(blocks)
    scene.volume.SetMapper(mapper)
    picture = scene.render()
    return float(picture[foreground(picture)].mean())


failures = []


def check(what, good):
    print(f"{what}: {'ok' if good else 'FAILED'}")
    if not good:
        failures.append(what)


check("before: VTK's mapper", vtkGPUVolumeRayCastMapper().GetClassName() != "vtkDeepShadowVolumeMapper")
check("Override('none')", vtkDeepShadowVolumeMapperFactory.Override("none"))
plain, mode = smart_rods()
check("vtkSmartVolumeMapper drew with its GPU mapper", mode == vtkSmartVolumeMapper.GPURenderMode)
plain_blocks = multiblock_rods()
check("Override('dsm')", vtkDeepShadowVolumeMapperFactory.Override("dsm"))
made = vtkGPUVolumeRayCastMapper()
check("New() makes ours with a deep shadow map", made.GetClassName() == "vtkDeepShadowVolumeMapper"
      and made.GetShadowTechnique().GetClassName() == "vtkDeepShadowDeepShadowMapTechnique")
shadowed, mode = smart_rods()
print(f"foreground mean: {shadowed:.1f} shadowed, {plain:.1f} unshadowed")
check("the shadowed rods are darker", shadowed < 0.95 * plain)
cells, _ = smart_rods(named_cells=True)
print(f"the cell array 'density' chosen by name: {cells:.1f} shadowed")
check("a cell array chosen by name draws the same rods", abs(cells - shadowed) < 0.1 * shadowed)
shadowed_blocks = multiblock_rods()
print(f"vtkMultiBlockVolumeMapper: {shadowed_blocks:.1f} shadowed, {plain_blocks:.1f} unshadowed")
check("vtkMultiBlockVolumeMapper draws ours too", abs(plain_blocks - plain) < 1.0
      and abs(shadowed_blocks - shadowed) < 1.0)
vtkDeepShadowVolumeMapperFactory.Restore()
check("Restore(): VTK's mapper again", vtkGPUVolumeRayCastMapper().GetClassName() != "vtkDeepShadowVolumeMapper")
sys.exit(1 if failures else 0)
