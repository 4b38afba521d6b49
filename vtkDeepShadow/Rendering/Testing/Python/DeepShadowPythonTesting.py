"""Shared pieces of the Python tests: a small shadowed scene, pixels as numbers."""
from vtkmodules.vtkRenderingCore import (vtkLight, vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkdeepshadow import vtkDeepShadowStandardScene, vtkDeepShadowVolumeMapper

BACKGROUND = (0.08, 0.09, 0.12)


class RodsScene:
    """The rods scene (rods shadow each other) with its key light, at `size` pixels; another
    standard scene by `name`."""

    def __init__(self, size=160, technique=None, name="rods"):
        self.scene = vtkDeepShadowStandardScene()
        self.scene.SetScene(name)
        self.scene.SetResolutionScale(0.5)
        self.mapper = vtkDeepShadowVolumeMapper()
        self.mapper.SetShadingModelToBlinnPhong()  # the scene's own look, as the tool draws it
        self.mapper.SetInputData(self.scene.GetVolume())
        self.mapper.SetShadowTechnique(technique)
        self.volume = vtkVolume()
        self.volume.SetMapper(self.mapper)
        self.volume.SetProperty(self.scene.GetVolumeProperty())
        self.renderer = vtkRenderer()
        self.renderer.SetBackground(*BACKGROUND)
        self.renderer.AddVolume(self.volume)
        self.scene.ApplyCamera(self.renderer.GetActiveCamera())
        self.renderer.ResetCameraClippingRange()
        light = vtkLight()
        light.SetLightTypeToSceneLight()
        light.SetPositional(False)
        center = self.volume.GetCenter()
        light.SetFocalPoint(center)
        light.SetPosition([c + d for c, d in zip(center, self.scene.GetLightDirection())])
        self.renderer.AddLight(light)
        self.light = light
        self.window = vtkRenderWindow()
        self.window.SetSize(size, size)
        self.window.AddRenderer(self.renderer)

    def render(self):
        """Renders and returns the pixels, an (h, w, 3) uint8 array."""
        self.window.Render()
        return pixels(self.window)


def pixels(window):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    image = grab.GetOutput()
    width, height, _ = image.GetDimensions()
    array = vtk_to_numpy(image.GetPointData().GetScalars())
    return array.reshape(height, width, -1)[:, :, :3]


def foreground(picture):
    """Mask of the pixels that are not the background."""
    background = [round(255 * c) for c in BACKGROUND]
    return (abs(picture.astype(int) - background).sum(axis=2) > 6)


def baseline_difference(picture, path):
    """(RMSE in [0, 1], share of pixels with a channel off by more than 8/255) against a PNG.
    The C++ tests' tolerance (BaselineTolerance in Cxx/DeepShadowTestUtilities.h) is RMSE
    <= 0.5/255 and share <= 0.1 %: VTK's vtkImageDifference forgives a swapped technique."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    baseline = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)[:, :, :3]
    if baseline.shape != picture.shape:
        return 1.0, 1.0
    difference = abs(picture.astype(float) - baseline) / 255.0
    return float((difference ** 2).mean() ** 0.5), float((difference.max(axis=2) > 8 / 255).mean())
