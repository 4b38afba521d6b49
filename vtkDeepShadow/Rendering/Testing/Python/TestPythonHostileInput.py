"""Hostile input II through the Python API (issue 45): a window size no framebuffer can have,
shadow techniques replaced many times, one volume in two windows, an extent past VTK's int
dimensions. Each gives one VTK error and a right picture afterwards, never a black picture,
leaked GPU memory or a stale window."""
import numpy
from vtkmodules.test import Testing
from vtkmodules.test.ErrorObserver import vtkErrorObserver
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkVolume
from vtkdeepshadow import vtkDeepShadowDeepShadowMapTechnique, vtkDeepShadowVolumeMapper
from DeepShadowPythonTesting import RodsScene, foreground, pixels


def rmse(a, b):
    return float(numpy.sqrt(((a.astype(float) - b.astype(float)) ** 2).mean()) / 255.0)


class TestPythonHostileInput(Testing.vtkTest):
    def testWindowSizeBeyondTheFramebufferLimit(self):
        scene = RodsScene(size=64)
        before = scene.render()
        observer = vtkErrorObserver()
        scene.window.AddObserver("ErrorEvent", observer)
        scene.window.SetSize(20000, 64)  # was: an all-black picture, no error
        self.assertIsNotNone(observer.error_message, "no error for a 20000-pixel side")
        self.assertIn("at most", scene.window.GetLastError())
        self.assertEqual(tuple(scene.window.GetSize()), (64, 64), "the size changed")
        after = scene.render()
        self.assertGreater(foreground(after).mean(), 0.05, "the picture after the error is blank")
        self.assertEqual(rmse(before, after), 0.0)

    def testReplacedTechniquesReleaseTheirMaps(self):
        scene = RodsScene(size=64, technique=vtkDeepShadowDeepShadowMapTechnique())
        reference = scene.render()
        old = scene.mapper.GetShadowTechnique()
        self.assertGreater(old.GetShadowBytes(), 0)
        for _ in range(5):
            old = scene.mapper.GetShadowTechnique()
            scene.mapper.SetShadowTechnique(vtkDeepShadowDeepShadowMapTechnique())
            # Was: its maps stayed on the GPU while Python held it (about 18 MB each time).
            self.assertEqual(old.GetShadowBytes(), 0, "the replaced technique kept its maps")
            self.assertEqual(rmse(scene.render(), reference), 0.0)

    def testOneVolumeInTwoWindows(self):
        first = RodsScene(size=96, technique=vtkDeepShadowDeepShadowMapTechnique())
        second_renderer = vtkRenderer()
        second_renderer.AddVolume(first.volume)
        second_renderer.AddLight(first.light)
        first.scene.ApplyCamera(second_renderer.GetActiveCamera())
        second_window = vtkRenderWindow()
        second_window.SetSize(128, 96)
        second_window.AddRenderer(second_renderer)
        first.render()
        second_window.Render()
        second = pixels(second_window)
        first.renderer.GetActiveCamera().Azimuth(30)
        turned = first.render()  # was: the first window kept its old picture, or went blank
        # The same view in a window of its own, with a mapper of its own.
        alone = RodsScene(size=96, technique=vtkDeepShadowDeepShadowMapTechnique())
        alone.renderer.SetActiveCamera(first.renderer.GetActiveCamera())
        self.assertLess(rmse(turned, alone.render()), 1e-9, "the first window is wrong")
        self.assertGreater(foreground(turned).mean(), 0.05)
        second_window.Render()
        self.assertLess(rmse(pixels(second_window), second), 1e-9, "the second window changed")

    def testExtentPastIntDimensions(self):
        image = vtkImageData()
        image.SetExtent(-2 ** 31, 2 ** 31 - 1, 0, 0, 0, 0)  # 2^32 points: GetDimensions() wraps to 0
        scalars = vtkUnsignedCharArray()
        scalars.SetNumberOfTuples(16)
        image.GetPointData().SetScalars(scalars)
        mapper = vtkDeepShadowVolumeMapper()
        mapper.SetInputData(image)
        observer = vtkErrorObserver()
        mapper.AddObserver("ErrorEvent", observer)
        volume = vtkVolume()
        volume.SetMapper(mapper)
        renderer = vtkRenderer()
        renderer.AddVolume(volume)
        window = vtkRenderWindow()
        window.SetSize(32, 32)
        window.AddRenderer(renderer)
        window.Render()
        self.assertIsNotNone(observer.error_message)
        self.assertIn("4294967296x1x1", mapper.GetLastError())  # was: "empty (no points)"


if __name__ == "__main__":
    Testing.main([(TestPythonHostileInput, "test")])
