"""Errors reach Python as VTK errors (ErrorEvent observers, GetLastError()) and a failed
render, never a crash of the interpreter: no input, an empty volume, a bad CSG expression,
a missing volume file, an unknown transfer-function preset or technique name."""
from vtkmodules.test import Testing
from vtkmodules.test.ErrorObserver import vtkErrorObserver
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkSphereSource
from vtkdeepshadow import (vtkDeepShadowCSGFilter, vtkDeepShadowDeepShadowMapTechnique,
                           vtkDeepShadowVolumeReader)
from DeepShadowPythonTesting import RodsScene, foreground


class TestPythonErrors(Testing.vtkTest):
    def renderWith(self, data):
        """Renders the rods scene with `data` as the mapper's input; returns
        (error message seen by an observer, the mapper's GetLastError(), covered fraction)."""
        scene = RodsScene(size=64, technique=vtkDeepShadowDeepShadowMapTechnique())
        if data is None:
            # SetInputData(None) is ambiguous in VTK's wrapping (vtkImageData or vtkDataSet
            # overloads, as for VTK's own volume mappers): None goes through the connection.
            scene.mapper.SetInputConnection(None)
        else:
            scene.mapper.SetInputData(data)
        observer = vtkErrorObserver()
        scene.mapper.AddObserver("ErrorEvent", observer)
        picture = scene.render()
        return observer.error_message, scene.mapper.GetLastError(), foreground(picture).mean()

    def testNoInput(self):
        seen, last, covered = self.renderWith(None)
        self.assertIsNotNone(seen, "no ErrorEvent for a mapper without input")
        self.assertIn("input", last.lower())
        self.assertEqual(covered, 0.0, "something was drawn without input")

    def testEmptyVolume(self):
        seen, last, covered = self.renderWith(vtkImageData())
        self.assertIsNotNone(seen, "no ErrorEvent for an empty volume")
        self.assertIn("empty", last.lower())
        self.assertEqual(covered, 0.0)

    def testBadCSGExpression(self):
        # The sources are kept: VTK 9.1's pipeline does not keep a producer alive through its
        # output port (vtkAppendPolyData crashes the same way with a temporary source).
        cube, sphere = vtkCubeSource(), vtkSphereSource()
        csg = vtkDeepShadowCSGFilter()
        csg.AddInputConnection(cube.GetOutputPort())
        csg.AddInputConnection(sphere.GetOutputPort())
        observer = vtkErrorObserver()
        csg.AddObserver("ErrorEvent", observer)
        csg.SetExpression("union(A,")
        csg.Update()
        self.assertIsNotNone(observer.error_message, "no ErrorEvent for a bad expression")
        self.assertNotEqual(csg.GetLastError(), "")
        self.assertEqual(csg.GetOutput().GetNumberOfCells(), 0)
        # The filter recovers once the expression is good.
        csg.SetExpression("union(A,B)")
        csg.Update()
        self.assertEqual(csg.GetLastError(), "")
        self.assertGreater(csg.GetOutput().GetNumberOfCells(), 0)

    def testMissingVolumeFile(self):
        reader = vtkDeepShadowVolumeReader()
        observer = vtkErrorObserver()
        reader.AddObserver("ErrorEvent", observer)
        reader.SetFileName("/nonexistent/volume.vti")
        reader.Update()
        self.assertIsNotNone(observer.error_message)
        self.assertIn("volume.vti", reader.GetLastError())

    def testTransferFunctionPresets(self):
        from vtkmodules.vtkRenderingCore import vtkVolumeProperty
        from vtkdeepshadow import vtkDeepShadowVolumePresets
        property_ = vtkVolumeProperty()
        presets = vtkDeepShadowVolumePresets()
        self.assertIn("CT-Bone", vtkDeepShadowVolumePresets.GetPresetNames())
        self.assertTrue(presets.ApplyPreset("CT-Bone", property_))
        self.assertEqual(property_.GetScalarOpacity().GetSize(), 4)
        observer = vtkErrorObserver()
        presets.AddObserver("ErrorEvent", observer)
        self.assertFalse(presets.Apply("CT-Teapot", property_))
        self.assertIsNotNone(observer.error_message)
        self.assertIn("neither a transfer-function preset", presets.GetLastError())
        self.assertEqual(property_.GetScalarOpacity().GetSize(), 4, "a failure changed it")

    def testUnknownTechniqueName(self):
        from vtkdeepshadow import vtkDeepShadowTechnique
        self.assertIsNone(vtkDeepShadowTechnique.NewFromName("nope"))
        self.assertIsNone(vtkDeepShadowTechnique.NewFromName(None))


if __name__ == "__main__":
    Testing.main([(TestPythonErrors, "test")])
