"""Scripts written after VTK's published volume examples run through the override
(vtkDeepShadowVolumeMapperFactory) and must draw VTK's picture: shaded composite under a key
light and a fill, clipping planes around a box, cropping, a light kit, two independent components
under MIP (the wavelet and its gradient magnitude, as VTK's independent-component MIP test), a
custom shader (a vtkShaderProperty replacement with a custom uniform), a label map with a label's
own colour and opacity, a 2D transfer function; a vtkSmartVolumeMapper
script keeps its smart-only calls when its class becomes vtkDeepShadowSmartVolumeMapper; and
a script that ends with `iren.Start()` runs with no display: Start() renders, saves the
picture VTK_DEEPSHADOW_SCREENSHOT names and returns.

Tolerance against VTK's picture: RMSE <= 0.01 for lighting, 0.02 for cuts (see SCRIPTS), or
1.5 times what VTK's own picture moves at 0.8 times its sample distance where that is more."""
import os
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkObject
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction, vtkPlane, vtkPlanes
from vtkmodules.vtkImagingCore import vtkImageAppendComponents, vtkRTAnalyticSource
from vtkmodules.vtkImagingGeneral import vtkImageGradientMagnitude
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkLightKit, vtkRenderer,
                                         vtkRenderWindow, vtkVolume, vtkVolumeProperty)
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkSmartVolumeMapper
from vtkdeepshadow import (vtkDeepShadowSmartVolumeMapper, vtkDeepShadowVolumeMapper,
                           vtkDeepShadowVolumeMapperFactory)
from DeepShadowPythonTesting import pixels

failures = []


def check(what, good):
    print(f"{what}: {'ok' if good else 'FAILED'}")
    if not good:
        failures.append(what)


def wavelet():
    """VTK's test data of choice: the analytic wavelet, 41^3."""
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-20, 20, -20, 20, -20, 20)
    source.Update()
    return source.GetOutput()


def colors(*nodes):
    """A vtkColorTransferFunction through (x, r, g, b) nodes."""
    function = vtkColorTransferFunction()
    for node in nodes:
        function.AddRGBPoint(*node)
    return function


def opacities(*nodes):
    """A vtkPiecewiseFunction through (x, y) nodes."""
    function = vtkPiecewiseFunction()
    for node in nodes:
        function.AddPoint(*node)
    return function


def shaded_property():
    prop = vtkVolumeProperty()
    prop.SetColor(colors((40, 0.1, 0.2, 0.9), (160, 0.9, 0.6, 0.2), (280, 1.0, 1.0, 0.8)))
    prop.SetScalarOpacity(opacities((40, 0.0), (150, 0.0), (200, 0.6), (280, 0.9)))
    prop.ShadeOn()
    prop.SetInterpolationTypeToLinear()
    prop.SetAmbient(0.2)
    prop.SetDiffuse(0.7)
    prop.SetSpecular(0.3)
    prop.SetSpecularPower(15.0)
    return prop


def key_and_fill(renderer):
    key = vtkLight()
    key.SetLightTypeToSceneLight()
    key.SetPosition(1.0, 1.0, 2.0)
    key.SetFocalPoint(0.0, 0.0, 0.0)
    fill = vtkLight()
    fill.SetLightTypeToSceneLight()
    fill.SetPosition(-1.0, -0.3, 1.0)
    fill.SetFocalPoint(0.0, 0.0, 0.0)
    fill.SetIntensity(0.4)
    renderer.AddLight(key)
    renderer.AddLight(fill)


def light_kit(renderer):
    vtkLightKit().AddLightsToRenderer(renderer)


def clip_box(mapper):
    """Six planes facing into a box (a volume mapper keeps what a plane's normal faces)."""
    box = vtkPlanes()
    box.SetBounds(-14.0, 10.0, -20.0, 8.0, -12.0, 16.0)
    for i in range(box.GetNumberOfPlanes()):
        outward = box.GetPlane(i)
        plane = vtkPlane()
        plane.SetOrigin(outward.GetOrigin())
        plane.SetNormal([-n for n in outward.GetNormal()])
        mapper.AddClippingPlane(plane)


def crop(mapper):
    mapper.SetCropping(True)
    mapper.SetCroppingRegionPlanes(-20.0, 4.0, -20.0, 20.0, -6.0, 20.0)
    mapper.SetCroppingRegionFlagsToSubVolume()


def independent_mip(mapper):
    """Two components, each with its own functions, projected by their maxima (unshaded)."""
    gradient = vtkImageGradientMagnitude()
    gradient.SetInputData(wavelet())
    both = vtkImageAppendComponents()
    both.AddInputData(wavelet())
    both.AddInputConnection(gradient.GetOutputPort())
    both.Update()
    mapper.SetInputData(both.GetOutput())
    mapper.SetBlendModeToMaximumIntensity()
    prop = shaded_property()
    prop.ShadeOff()
    prop.SetIndependentComponents(True)
    prop.SetColor(1, colors((0.0, 0.0, 0.1, 0.0), (20.0, 0.2, 1.0, 0.3)))
    prop.SetScalarOpacity(1, opacities((0.0, 0.0), (20.0, 0.8)))
    return prop


def image_of(values, origin=(0.0, 0.0, 0.0)):
    """A vtkImageData of `values` (indexed [z][y][x], or [y][x][component] for a 2D image)."""
    image = vtkImageData()
    if values.ndim == 3 and values.dtype == np.uint8:
        image.SetDimensions(values.shape[2], values.shape[1], values.shape[0])
        components = 1
    else:
        image.SetDimensions(values.shape[1], values.shape[0], 1)
        components = values.shape[2]
    image.SetOrigin(origin)
    image.GetPointData().SetScalars(numpy_to_vtk(values.reshape(-1, components), deep=True))
    return image


def label_map(mapper):
    """Labels 1 (a ball, red and denser) and 2 (the half x < 0, its own faint opacity)."""
    z, y, x = np.mgrid[-20:21, -20:21, -20:21]
    labels = np.where(x * x + y * y + z * z < 144, 1, np.where(x < 0, 2, 0)).astype(np.uint8)
    mapper.SetMaskInput(image_of(labels, (-20.0, -20.0, -20.0)))
    mapper.SetMaskTypeToLabelMap()
    prop = shaded_property()
    prop.SetLabelColor(1, colors((40, 0.4, 0.0, 0.0), (280, 1.0, 0.3, 0.2)))
    prop.SetLabelScalarOpacity(1, opacities((40, 0.0), (120, 0.0), (280, 0.8)))
    prop.SetLabelScalarOpacity(2, opacities((40, 0.0), (200, 0.0), (280, 0.2)))
    return prop


def transfer_2d(mapper):
    """A 256 x 128 RGBA function: blue to orange along the scalar, opacity rising with both."""
    g, v = np.mgrid[0:128, 0:256] / np.array([[[127.0]], [[255.0]]])
    rgba = np.stack([0.2 + 0.8 * v, 0.3 + 0.4 * v, 1.0 - 0.8 * v, np.clip(v - 0.45, 0, 1) * (0.2 + 0.8 * g)], axis=-1)
    prop = shaded_property()
    prop.SetTransferFunction2D(image_of(rgba.astype(np.float32)))
    prop.SetTransferFunctionMode(vtkVolumeProperty.TF_2D)
    return prop


def custom_shader(mapper):
    """VTK's custom-shader example's way: a tint by a custom uniform at //VTK::Base::Exit."""
    mapper.tinted = True


def draw(make_mapper, lights, configure=None, size=160, step=0.5):
    """A VTK example's pipeline: the wavelet, shaded, seen from an angle. `configure(mapper)`
    may return a property of its own."""
    mapper = make_mapper()
    mapper.SetInputData(wavelet())
    mapper.SetAutoAdjustSampleDistances(False)
    mapper.SetSampleDistance(step)
    prop = configure(mapper) if configure else None
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop or shaded_property())
    if getattr(mapper, "tinted", False):
        shader = volume.GetShaderProperty()
        shader.GetFragmentCustomUniforms().SetUniform3f("u_tint", [1.0, 0.45, 0.2])
        shader.AddFragmentShaderReplacement("//VTK::Base::Exit", True,
                                            "//VTK::Base::Exit\n  g_fragColor.rgb *= u_tint;", False)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(35.0)
    renderer.GetActiveCamera().Elevation(25.0)
    renderer.ResetCamera()
    lights(renderer)
    window = vtkRenderWindow()
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    window.Render()
    return pixels(window) / 255.0, mapper


def rmse(a, b):
    return float(np.sqrt(((a - b) ** 2).mean()))


# Each script with its bound: 0.01 for lighting alone, 0.02 (VTK's noise, the bound for
# published scripts) where cut faces cross the wavelet's fine structure: VTK starts its rays on
# a clipping plane, we keep the samples' phase from the box (measured 0.0126 clipped). The MIP
# measured 0.0071 (0.0099 before its samples started at the ray's entry, as VTK's do).
SCRIPTS = {
    "shaded composite under a key light and a fill": (key_and_fill, None, 0.01),
    "shaded composite under a light kit": (light_kit, None, 0.01),
    "clipping planes around a box": (key_and_fill, clip_box, 0.02),
    "cropping to a sub-volume": (key_and_fill, crop, 0.02),
    "two independent components under MIP": (key_and_fill, independent_mip, 0.01),
    "a custom shader tinting by a custom uniform": (key_and_fill, custom_shader, 0.01),
    "a label map with a label's own colour and opacity": (key_and_fill, label_map, 0.01),
    "a 2D transfer function": (key_and_fill, transfer_2d, 0.01),
}

for name, (lights, configure, floor) in SCRIPTS.items():
    vtkDeepShadowVolumeMapperFactory.Restore()
    vtks, theirs = draw(vtkGPUVolumeRayCastMapper, lights, configure)
    # VTK's own noise: its picture at 0.8 times the sample distance.
    noise = rmse(draw(vtkGPUVolumeRayCastMapper, lights, configure, step=0.4)[0], vtks)
    bound = max(floor, 1.5 * noise)
    vtkDeepShadowVolumeMapperFactory.Override("none")
    ours, mapper = draw(vtkGPUVolumeRayCastMapper, lights, configure)
    vtkDeepShadowVolumeMapperFactory.Restore()
    drawn = (vtks.max(axis=2) > 0.02).mean()
    difference = rmse(ours, vtks)
    print(f"{name}: {mapper.GetClassName()} against {theirs.GetClassName()}: RMSE {difference:.5f} "
          f"(VTK against itself at 0.8x its step: {noise:.5f}), VTK's picture covers {100 * drawn:.1f} %")
    check(f"{name}: drawn by ours through the override", mapper.GetClassName() == "vtkDeepShadowVolumeMapper")
    check(f"{name}: VTK's picture is not empty", drawn > 0.1)
    check(f"{name}: VTK's picture (RMSE <= {bound:.4f})", difference <= bound)

# The custom shader's check can fail: the tint changes VTK's picture.
tinted, _ = draw(vtkGPUVolumeRayCastMapper, key_and_fill, custom_shader)
plain, _ = draw(vtkGPUVolumeRayCastMapper, key_and_fill)
print(f"VTK's picture tinted against untinted: RMSE {rmse(tinted, plain):.5f}")
check("the tint shows in VTK's picture", rmse(tinted, plain) > 0.02)

# The check can fail: another light is another picture.
vtks, _ = draw(vtkGPUVolumeRayCastMapper, key_and_fill)
other, _ = draw(vtkGPUVolumeRayCastMapper, light_kit)
print(f"key and fill against a light kit, both VTK's: RMSE {rmse(vtks, other):.5f}")
check("the comparison tells two lightings apart", rmse(vtks, other) > 0.02)

# A smart-mapper script with its class name swapped keeps its smart-only calls.


def smart(cls):
    def make():
        mapper = cls()
        mapper.SetRequestedRenderModeToGPU()
        mapper.SetInteractiveUpdateRate(2.0)
        return mapper
    return make


vtks, _ = draw(smart(vtkSmartVolumeMapper), key_and_fill)
ours, mapper = draw(smart(vtkDeepShadowSmartVolumeMapper), key_and_fill)
print(f"vtkDeepShadowSmartVolumeMapper against vtkSmartVolumeMapper: RMSE {rmse(ours, vtks):.5f}")
check("the smart mapper's GPU mapper is ours", mapper.GetDeepShadowMapper().GetClassName() == "vtkDeepShadowVolumeMapper"
      and mapper.GetLastUsedRenderMode() == vtkSmartVolumeMapper.GPURenderMode)
check("vtkDeepShadowSmartVolumeMapper draws VTK's picture (RMSE <= 0.01)", rmse(ours, vtks) <= 0.01)
mapper.SetRequestedRenderModeToRayCast()
check("SetRequestedRenderModeToRayCast() still works", mapper.GetRequestedRenderMode() == vtkSmartVolumeMapper.RayCastRenderMode)

# Shadows through the smart mapper: its GPU mapper takes the technique.
from vtkdeepshadow import vtkDeepShadowDeepShadowMapTechnique  # noqa: E402


def smart_shadowed():
    mapper = smart(vtkDeepShadowSmartVolumeMapper)()
    mapper.SetShadowTechnique(vtkDeepShadowDeepShadowMapTechnique())
    return mapper


shadowed, mapper = draw(smart_shadowed, key_and_fill)
print(f"the smart mapper with a deep shadow map: mean {shadowed.mean():.4f}, without {ours.mean():.4f}")
check("the smart mapper draws shadows when given a technique", mapper.GetShadowTechnique() is not None
      and shadowed.mean() < 0.97 * ours.mean())

# A script ending in iren.Start(), with no display, in a fresh interpreter: it returns, and
# the screenshot is the window's picture.
SCRIPT = """
import vtkdeepshadow
import vtkmodules.vtkInteractionStyle
import vtkmodules.vtkRenderingUI  # VTK's X11 interactor registers after ours
from vtkmodules.vtkImagingCore import vtkImageAppendComponents, vtkRTAnalyticSource
from vtkmodules.vtkImagingGeneral import vtkImageGradientMagnitude
from vtkmodules.vtkRenderingCore import (vtkRenderer, vtkRenderWindow, vtkRenderWindowInteractor,
                                         vtkVolume, vtkVolumeProperty, vtkColorTransferFunction)
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingVolumeOpenGL2
source = vtkRTAnalyticSource()
mapper = vtkGPUVolumeRayCastMapper()
mapper.SetInputConnection(source.GetOutputPort())
color = vtkColorTransferFunction(); color.AddRGBPoint(40, 0, 0, 1); color.AddRGBPoint(280, 1, 1, 0)
opacity = vtkPiecewiseFunction(); opacity.AddPoint(40, 0); opacity.AddPoint(280, 0.2)
prop = vtkVolumeProperty(); prop.SetColor(color); prop.SetScalarOpacity(opacity)
volume = vtkVolume(); volume.SetMapper(mapper); volume.SetProperty(prop)
renderer = vtkRenderer(); renderer.AddVolume(volume)
window = vtkRenderWindow(); window.SetSize(120, 100); window.AddRenderer(renderer)
iren = vtkRenderWindowInteractor(); iren.SetRenderWindow(window)
iren.Initialize()
iren.Start()
print("returned", iren.GetClassName(), window.GetClassName())
"""
with tempfile.TemporaryDirectory() as directory:
    screenshot = os.path.join(directory, "start.png")
    env = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="", VTK_DEEPSHADOW_SCREENSHOT=screenshot)
    run = subprocess.run([sys.executable, "-c", SCRIPT], env=env, capture_output=True, text=True, timeout=300)
    print(run.stdout.strip(), run.stderr.strip()[-300:])
    check("iren.Start() returns with no display", run.returncode == 0 and
          "returned vtkDeepShadowHeadlessInteractor vtkDeepShadowRenderWindow" in run.stdout)
    written = os.path.exists(screenshot)
    check("Start() saved the picture VTK_DEEPSHADOW_SCREENSHOT names", written)
    if written:
        from vtkmodules.vtkIOImage import vtkPNGReader
        from vtkmodules.util.numpy_support import vtk_to_numpy
        reader = vtkPNGReader()
        reader.SetFileName(screenshot)
        reader.Update()
        width, height, _ = reader.GetOutput().GetDimensions()
        values = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
        print(f"screenshot {width}x{height}, mean {values.mean():.1f}, max {values.max()}")
        check("the screenshot is the window's size and not blank", (width, height) == (120, 100) and values.max() > 50)
    bad = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True, timeout=300,
                         env=dict(env, VTK_DEEPSHADOW_SCREENSHOT=os.path.join(directory, "no", "such", "dir.png")))
    check("a screenshot that cannot be written is one error", "VTK_DEEPSHADOW_SCREENSHOT: cannot write" in bad.stderr)

vtkObject.GlobalWarningDisplayOff()
sys.exit(1 if failures else 0)
