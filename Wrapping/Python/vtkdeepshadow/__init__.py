"""vtkDeepShadow for VTK pipelines in Python.

Volume rendering with shadows (deep shadow maps and the other techniques of the module), a
headless render window (OSMesa or EGL, no display needed), the CPU reference renderer, CSG
bounds and the standard scenes. The classes are ordinary VTK objects and mix with
``vtkmodules`` ones::

    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkVolume
    from vtkdeepshadow import vtkDeepShadowVolumeMapper, vtkDeepShadowRenderWindow

Importing this package registers the headless window as the ``vtkRenderWindow`` override when
the process has no display (see vtkDeepShadowRenderWindow), whatever was imported first.
"""

from .vtkDeepShadowRendering import *  # noqa: F401,F403
from .vtkDeepShadowScenes import *  # noqa: F401,F403
from .vtkDeepShadowCSG import *  # noqa: F401,F403
