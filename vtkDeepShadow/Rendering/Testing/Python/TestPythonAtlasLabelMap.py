"""A real brain atlas as a label map, as a user would draw one: the Colin27 T1 MRI (mricron's
ch2.nii.gz) masked by the AAL atlas on the same grid (aal.nii.gz, regions 1-116), each region
with a colour of its own and every seventh one opaque, drawn by VTK's mapper and by ours
through the factory override in one run. Ours must match VTK's picture within VTK's own noise
(its picture at 0.8 times the sample distance, at least 0.01); the check must fail for other
regions made opaque, and for the volume drawn without the atlas. Skipped where mricron-data
is not installed."""
import os

import numpy
from vtkmodules.test import Testing
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkNIFTIImageReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkVolumeProperty)
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
from vtkdeepshadow import vtkDeepShadowVolumeMapperFactory
from DeepShadowPythonTesting import pixels

TEMPLATES = "/usr/share/mricron/templates"


def read(name):
    reader = vtkNIFTIImageReader()
    reader.SetFileName(os.path.join(TEMPLATES, name))
    reader.Update()
    return reader.GetOutput()


def rmse(a, b):
    return float(numpy.sqrt(((a - b) ** 2).mean()))


class TestPythonAtlasLabelMap(Testing.vtkTest):
    def setUp(self):
        for name in ("ch2.nii.gz", "aal.nii.gz"):
            if not os.path.exists(os.path.join(TEMPLATES, name)):
                self.skipTest(os.path.join(TEMPLATES, name) + " is not installed (mricron-data)")
        self.brain = read("ch2.nii.gz")
        self.atlas = read("aal.nii.gz")
        # The same 181x217x181 grid; the atlas is placed where the brain is.
        self.assertEqual(self.brain.GetDimensions(), self.atlas.GetDimensions())
        self.atlas.SetSpacing(self.brain.GetSpacing())
        self.atlas.SetOrigin(self.brain.GetOrigin())

    def property(self, opaque):
        """The brain faint and grey; region k in a colour of its own, opaque where opaque(k)."""
        low, high = self.brain.GetScalarRange()
        color = vtkColorTransferFunction()
        color.AddRGBPoint(low, 0.0, 0.0, 0.0)
        color.AddRGBPoint(high, 0.9, 0.85, 0.8)
        opacity = vtkPiecewiseFunction()
        opacity.AddPoint(low, 0.0)
        opacity.AddPoint(low + 0.3 * (high - low), 0.0)
        opacity.AddPoint(high, 0.05)
        prop = vtkVolumeProperty()
        prop.SetColor(color)
        prop.SetScalarOpacity(opacity)
        prop.SetInterpolationTypeToLinear()
        prop.ShadeOn()
        shades = numpy.random.default_rng(3).random((117, 3))
        for k in range(1, int(self.atlas.GetScalarRange()[1]) + 1):
            region = vtkColorTransferFunction()
            region.AddRGBPoint(low, *shades[k])
            region.AddRGBPoint(high, *shades[k])
            regionOpacity = vtkPiecewiseFunction()
            regionOpacity.AddPoint(low, 0.0)
            regionOpacity.AddPoint(low + 0.3 * (high - low), 0.0)
            regionOpacity.AddPoint(high, 0.5 if opaque(k) else 0.0)
            prop.SetLabelColor(k, region)
            prop.SetLabelScalarOpacity(k, regionOpacity)
        return prop

    def draw(self, ours, opaque=lambda k: k % 7 == 0, step=1.0, atlas=True):
        if ours:
            vtkDeepShadowVolumeMapperFactory.Override("none")
        try:
            mapper = vtkGPUVolumeRayCastMapper()
        finally:
            vtkDeepShadowVolumeMapperFactory.Restore()
        mapper.SetInputData(self.brain)
        if atlas:
            mapper.SetMaskInput(self.atlas)
            mapper.SetMaskTypeToLabelMap()
        mapper.SetAutoAdjustSampleDistances(False)
        mapper.SetSampleDistance(step)
        volume = vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(self.property(opaque))
        renderer = vtkRenderer()
        renderer.AddVolume(volume)
        renderer.ResetCamera()
        renderer.GetActiveCamera().Elevation(-70.0)
        renderer.GetActiveCamera().OrthogonalizeViewUp()
        renderer.ResetCamera()
        window = vtkRenderWindow()
        window.SetSize(200, 200)
        window.AddRenderer(renderer)
        window.Render()
        self.assertEqual(mapper.GetClassName(), "vtkDeepShadowVolumeMapper" if ours else
                         "vtkOpenGLGPUVolumeRayCastMapper")
        return pixels(window) / 255.0

    def test_atlas_matches_vtk(self):
        vtks = self.draw(False)
        noise = rmse(self.draw(False, step=0.8), vtks)
        bound = max(0.01, 1.5 * noise)
        ours = self.draw(True)
        covered = (vtks.max(axis=2) > 0.02).mean()
        difference = rmse(ours, vtks)
        print(f"the AAL atlas over Colin27: ours against VTK's RMSE {difference:.5f} (VTK against itself at "
              f"0.8x its step {noise:.5f}, bound {bound:.4f}); VTK's picture covers {100 * covered:.1f} %")
        self.assertGreater(covered, 0.1)
        self.assertLessEqual(difference, bound)
        # The check can fail: other regions opaque, or no atlas at all.
        others = rmse(self.draw(True, opaque=lambda k: k % 7 == 3), vtks)
        unmasked = rmse(self.draw(True, atlas=False), vtks)
        print(f"ours with other regions opaque: {others:.5f}; without the atlas: {unmasked:.5f} (must exceed)")
        self.assertGreater(others, bound)
        self.assertGreater(unmasked, bound)


if __name__ == "__main__":
    Testing.main([(TestPythonAtlasLabelMap, "test")])
