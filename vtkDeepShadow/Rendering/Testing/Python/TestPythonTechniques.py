"""Every technique class from Python: constructs, sets and gets (clamped to the registry's
ranges), fires observers, renders, and darkens the scene it shadows."""
import vtkdeepshadow
from vtkmodules.test import Testing
from vtkdeepshadow import vtkDeepShadowTechnique
from DeepShadowPythonTesting import RodsScene, foreground

# The bases of the techniques are abstract; every other *Technique class is one.
ABSTRACT = {"vtkDeepShadowTechnique", "vtkDeepShadowLightSpaceTechnique"}
TECHNIQUE_CLASSES = [
    getattr(vtkdeepshadow, name) for name in sorted(dir(vtkdeepshadow))
    if name.endswith("Technique") and name not in ABSTRACT]


def clamped_parameters(technique):
    """(name, low, high) of every vtkSetClampMacro parameter the object has."""
    for attribute in dir(technique):
        if attribute.startswith("Get") and attribute.endswith("MinValue"):
            name = attribute[3:-len("MinValue")]
            if hasattr(technique, "Set" + name) and hasattr(technique, "Get" + name):
                yield (name, getattr(technique, attribute)(),
                       getattr(technique, "Get%sMaxValue" % name)())


def luminance(picture):
    return picture.astype(float) @ [0.2126, 0.7152, 0.0722]


class TestPythonTechniques(Testing.vtkTest):
    @classmethod
    def setUpClass(cls):
        unshadowed = RodsScene()
        cls.unshadowed = luminance(unshadowed.render())
        cls.mask = foreground(unshadowed.render())

    def testEveryTechniqueIsWrapped(self):
        # Every registry name is made by one of the wrapped classes (eight kinds, five classes).
        for name in ("rays", "rays-opaque", "rays-color", "shadowmap", "dsm", "dsm-color",
                     "dsm-clustered", "dsm3", "cssm", "dsm-cached"):
            technique = vtkDeepShadowTechnique.NewFromName(name)
            self.assertIsNotNone(technique, name)
            self.assertEqual(technique.GetName(), name)
            self.assertIn(type(technique), TECHNIQUE_CLASSES, name)
        self.assertIsNone(vtkDeepShadowTechnique.NewFromName("no-such-technique"))
        for name in ABSTRACT:
            with self.assertRaises(TypeError):
                getattr(vtkdeepshadow, name)()

    def testClusteredMapsOnASparseScene(self):
        # dsm-clustered: several fitted maps for the sparse scene's far-apart objects, a
        # darker picture than none; with Clusters 0 the same class draws one map.
        unshadowed = RodsScene(name="sparse")
        lit = luminance(unshadowed.render())
        mask = foreground(unshadowed.render())
        technique = vtkDeepShadowTechnique.NewFromName("dsm-clustered")
        self.assertEqual((technique.GetClusters(), technique.GetMapSize()), (4, 256))
        scene = RodsScene(technique=technique, name="sparse")
        shadowed = luminance(scene.render())
        self.assertEqual(scene.mapper.GetLastError(), "")
        counts = technique.GetClusterCounts()
        self.assertEqual(len(counts), 1)
        self.assertTrue(2 <= counts[0] <= 4, counts)
        self.assertLess(shadowed[mask].mean(), 0.95 * lit[mask].mean())
        technique.SetClusters(0)
        scene.render()
        self.assertEqual(tuple(technique.GetClusterCounts()), (0,))

    def testChunkedNodeMemory(self):
        # SetChunkNodes: the picture of fixed layers that hold every node, every node kept,
        # the memory of the chunks in use.
        technique = vtkDeepShadowTechnique.NewFromName("dsm")
        technique.SetLayers(64)
        scene = RodsScene(technique=technique)
        layers = scene.render()
        self.assertEqual(technique.GetTexelsOverflowed(), 0)
        layer_bytes = technique.GetShadowBytes()
        technique.SetLayers(8)
        technique.SetChunkNodes(4)
        chunked = scene.render()
        self.assertEqual(scene.mapper.GetLastError(), "")
        self.assertEqual(technique.GetTexelsOverflowed(), 0)
        self.assertGreater(technique.GetChunksUsed(), 0)
        self.assertEqual(technique.GetChunkBytes(), 40)
        self.assertLess(technique.GetShadowBytes(), layer_bytes / 4)
        self.assertTrue((chunked == layers).all())
        # The same figures through the statistics any caller reads without knowing the class.
        self.assertEqual(technique.GetStatistic("chunks_used"), technique.GetChunksUsed())
        self.assertEqual(technique.GetStatistic("dsm_nodes_max"), technique.GetNodesMax())

    def testStatisticsByName(self):
        # Each technique's statistics (names and values) after a frame: shadow rays report
        # none, deep shadow maps their nodes, resolution-matched maps their pages.
        expected = {"rays": set(), "dsm": {"dsm_nodes_avg", "dsm_nodes_max", "chunks_used", "clusters"},
                    "rmsm": {"pages_requested", "pages_unique", "superpages", "atlas_bytes"}}
        for name, names in expected.items():
            technique = vtkDeepShadowTechnique.NewFromName(name)
            RodsScene(technique=technique).render()
            reported = technique.GetStatisticNames()
            self.assertTrue(names <= set(reported), (name, reported))
            self.assertEqual(len(set(reported)), len(reported), name)
            if name != "rays":
                counted = "dsm_nodes_max" if name == "dsm" else "pages_unique"
                self.assertGreater(technique.GetStatistic(counted), 0, name)
            self.assertEqual(technique.GetStatistic("no_such_statistic"), 0.0)

    def testSetGetAndObservers(self):
        for cls in TECHNIQUE_CLASSES:
            technique = cls()
            self.assertTrue(technique.IsA("vtkDeepShadowTechnique"), cls.__name__)
            modified = []
            technique.AddObserver("ModifiedEvent", lambda *args: modified.append(1))
            parameters = list(clamped_parameters(technique))
            self.assertTrue(parameters, cls.__name__ + " has no clamped parameters")
            for name, low, high in parameters:
                get, set_ = getattr(technique, "Get" + name), getattr(technique, "Set" + name)
                default = get()
                self.assertTrue(low <= default <= high, (cls.__name__, name, default))
                set_(high)
                self.assertEqual(get(), high, (cls.__name__, name))
                set_(low - 1)
                self.assertEqual(get(), low, (cls.__name__, name, "below the range clamps"))
                set_(default)
                self.assertEqual(get(), default)
            self.assertTrue(modified, cls.__name__ + ": no ModifiedEvent")

    def testEveryTechniqueDarkensTheScene(self):
        lit = self.unshadowed[self.mask].mean()
        for cls in TECHNIQUE_CLASSES:
            scene = RodsScene(technique=cls())
            ended = []
            scene.window.AddObserver("EndEvent", lambda *args: ended.append(1))
            shadowed = luminance(scene.render())
            self.assertEqual(scene.mapper.GetLastError(), "", cls.__name__)
            self.assertTrue(ended, "no EndEvent")
            technique = scene.mapper.GetShadowTechnique()
            # Shadow rays cast per sample and build nothing; every other technique builds once.
            self.assertEqual(technique.GetBuildCount(), 0 if technique.GetName() == "rays" else 1,
                             technique.GetName())
            dark = shadowed[self.mask].mean()
            self.assertLess(dark, 0.97 * lit, "%s does not darken: %.1f vs %.1f"
                            % (cls.__name__, dark, lit))
            # A shadow never lights: no pixel gets noticeably brighter.
            brighter = (shadowed - self.unshadowed)[self.mask]
            self.assertLess((brighter > 4).mean(), 0.01, cls.__name__)

    def testRebuildsOnlyWhenTheLightMoves(self):
        scene = RodsScene(technique=vtkDeepShadowTechnique.NewFromName("dsm"))
        technique = scene.mapper.GetShadowTechnique()
        scene.render()
        scene.renderer.GetActiveCamera().Azimuth(20)
        scene.render()
        self.assertEqual(technique.GetBuildCount(), 1, "a camera move rebuilt the shadows")
        x, y, z = scene.light.GetPosition()
        scene.light.SetPosition(x + 1.0, y, z)
        scene.render()
        self.assertEqual(technique.GetBuildCount(), 2, "a light move did not rebuild them")


if __name__ == "__main__":
    Testing.main([(TestPythonTechniques, "test")])
