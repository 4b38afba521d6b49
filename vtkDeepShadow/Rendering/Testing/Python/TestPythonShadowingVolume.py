"""A mesh receives a volume's shadow without vtkDeepShadowPass, from Python
(vtkDeepShadowPolyDataMapper.SetShadowingVolume): the rods scene over a ground plane on the side
away from its light. With the volume named, the ground darkens where the rods shadow it; with
ReceiveShadows off it does not (the check must be able to fail)."""
from vtkmodules.test import Testing
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor
from vtkdeepshadow import vtkDeepShadowDeepShadowMapTechnique, vtkDeepShadowPolyDataMapper
from DeepShadowPythonTesting import RodsScene


def ground_under(volume, toward_light):
    """A plane beyond the volume's box on the side away from the light, twice its size."""
    bounds = volume.GetBounds()
    axis = max(range(3), key=lambda a: abs(toward_light[a]))
    low = toward_light[axis] > 0  # the light is on the high side: the ground on the low one
    u, v = (axis + 1) % 3, (axis + 2) % 3
    extent = bounds[2 * axis + 1] - bounds[2 * axis]
    level = bounds[2 * axis] - 0.05 * extent if low else bounds[2 * axis + 1] + 0.05 * extent

    def point(cu, cv):
        p = [0.0, 0.0, 0.0]
        p[axis] = level
        du, dv = bounds[2 * u + 1] - bounds[2 * u], bounds[2 * v + 1] - bounds[2 * v]
        p[u] = bounds[2 * u] - 0.5 * du + cu * 2 * du
        p[v] = bounds[2 * v] - 0.5 * dv + cv * 2 * dv
        return p

    plane = vtkPlaneSource()
    plane.SetOrigin(point(0, 0))
    plane.SetPoint1(point(1, 0))
    plane.SetPoint2(point(0, 1))
    plane.Update()
    return plane.GetOutput()


class TestPythonShadowingVolume(Testing.vtkTest):
    def testGroundReceivesTheVolumesShadow(self):
        scene = RodsScene(size=200, technique=vtkDeepShadowDeepShadowMapTechnique())
        mapper = vtkDeepShadowPolyDataMapper()
        mapper.SetInputData(ground_under(scene.volume, scene.scene.GetLightDirection()))
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(0.85, 0.85, 0.8)
        scene.renderer.AddActor(actor)
        scene.renderer.ResetCamera()
        lit = scene.render().astype(float).sum()
        mapper.SetShadowingVolume(scene.volume)
        self.assertIs(mapper.GetShadowingVolume(), scene.volume)
        shadowed = scene.render().astype(float).sum()
        self.assertEqual(mapper.GetLastError(), "")
        self.assertIn("Shadow:dsm", mapper.GetShaderFeatures())
        mapper.ReceiveShadowsOff()
        not_received = scene.render().astype(float).sum()
        print("picture sums: ground lit %.0f, receiving %.0f, ReceiveShadows off %.0f"
              % (lit, shadowed, not_received))
        self.assertLess(shadowed, 0.97 * lit)
        self.assertEqual(not_received, lit)


if __name__ == "__main__":
    Testing.main([(TestPythonShadowingVolume, "test")])
