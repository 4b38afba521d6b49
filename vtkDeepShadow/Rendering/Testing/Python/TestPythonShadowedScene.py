"""Regression image from Python: the rods scene with deep shadow maps, compared with the
committed baseline by VTK's own image comparison (vtkmodules.test.Testing), then with the
C++ tests' tolerance, which also tells techniques apart."""
from vtkmodules.test import Testing
from vtkdeepshadow import vtkDeepShadowDeepShadowMapTechnique, vtkDeepShadowRenderWindow
from DeepShadowPythonTesting import RodsScene, baseline_difference, foreground


class TestPythonShadowedScene(Testing.vtkTest):
    def testDeepShadowMaps(self):
        scene = RodsScene(size=200, technique=vtkDeepShadowDeepShadowMapTechnique())
        picture = scene.render()
        self.assertIsInstance(scene.window, vtkDeepShadowRenderWindow)
        self.assertEqual(scene.mapper.GetLastError(), "")
        # Not a blank picture: the rods cover a good part of it.
        self.assertGreater(foreground(picture).mean(), 0.05)
        baseline = Testing.getAbsImagePath("TestPythonShadowedScene.png")
        Testing.compareImage(scene.window, baseline)
        rmse, share = baseline_difference(picture, baseline)
        self.assertLessEqual(rmse, 0.5 / 255, "RMSE %.5f against %s" % (rmse, baseline))
        self.assertLessEqual(share, 0.001, "%.3f %% of the pixels differ" % (100 * share))


if __name__ == "__main__":
    Testing.main([(TestPythonShadowedScene, "test")])
