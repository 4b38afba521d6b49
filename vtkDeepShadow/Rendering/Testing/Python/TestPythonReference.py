"""The CPU reference renderer from Python: the GPU's deep-shadow-map picture is close to the
ground truth (translucent shadow rays, double precision), the unshadowed one is not; the
enums come through as class constants. An interactive frame with its shadows from a coarser
grid (InteractiveShadowSubsampling) matches the reference renderer's twin of it."""
from vtkmodules.test import Testing
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkdeepshadow import (vtkDeepShadowDeepShadowMapTechnique, vtkDeepShadowReferenceRenderer,
                           vtkDeepShadowRenderWindow)
from DeepShadowPythonTesting import RodsScene


def rmse(a, b):
    return float((((a.astype(float) - b) / 255.0) ** 2).mean() ** 0.5)


class TestPythonReference(Testing.vtkTest):
    def reference(self, scene, subsampling=0):
        renderer = vtkDeepShadowReferenceRenderer()
        if subsampling:
            renderer.SetGpuTwin(True)
            renderer.SetShadowSubsampling(subsampling)
        else:
            renderer.SetShadows(vtkDeepShadowReferenceRenderer.GroundTruthShadows)
            self.assertEqual(renderer.GetShadows(), 1)
        image = vtkImageData()
        self.assertTrue(renderer.Render(scene.renderer, image), renderer.GetLastError())
        width, height, _ = image.GetDimensions()
        return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, 3)

    def testGroundTruth(self):
        self.assertEqual((vtkDeepShadowRenderWindow.OSMesa, vtkDeepShadowRenderWindow.EGL), (1, 2))
        shadowed = RodsScene(size=96, technique=vtkDeepShadowDeepShadowMapTechnique())
        gpu = shadowed.render()
        truth = self.reference(shadowed)
        unshadowed = RodsScene(size=96).render()
        close, far = rmse(gpu, truth), rmse(unshadowed, truth)
        print("RMSE against the ground truth: deep shadow maps %.4f, no shadows %.4f" % (close, far))
        self.assertLess(close, 0.02)
        self.assertGreater(far, 3 * close)

    def testInteractiveShadowsFromACoarserGrid(self):
        scene = RodsScene(size=96, technique=vtkDeepShadowDeepShadowMapTechnique())
        scene.render()  # still: the maps in full
        scene.mapper.SetInteractiveShadowSubsampling(4)
        scene.window.SetDesiredUpdateRate(5.0)  # what an interactor asks for while it moves
        gpu = scene.render()
        self.assertIn("ray-cast-coarse-shadows", scene.mapper.GetLastPasses())
        difference = rmse(gpu, self.reference(scene, 4))
        print("interactive frame against its twin: RMSE %.4f" % difference)
        self.assertLess(difference, 2.0 / 255.0)
        scene.window.SetDesiredUpdateRate(0.0001)
        scene.render()
        self.assertNotIn("ray-cast-coarse-shadows", scene.mapper.GetLastPasses())


if __name__ == "__main__":
    Testing.main([(TestPythonReference, "test")])
