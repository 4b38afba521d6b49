#include "vtkDeepShadowRenderingObjectFactory.h"

#include "vtkDeepShadowHeadlessInteractor.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapperFactory.h"
#include "vtkVersion.h"

#include <cstdlib>
#include <cstring>

vtkStandardNewMacro(vtkDeepShadowRenderingObjectFactory);

namespace
{
vtkObject* CreateHeadlessRenderWindow()
{
  return vtkDeepShadowRenderWindow::New();
}

vtkObject* CreateHeadlessInteractor()
{
  return vtkDeepShadowHeadlessInteractor::New();
}

bool IsSet(const char* name)
{
  const char* value = std::getenv(name);
  return value && *value;
}
}

vtkDeepShadowRenderingObjectFactory::vtkDeepShadowRenderingObjectFactory()
{
  this->RegisterOverride("vtkRenderWindow", "vtkDeepShadowRenderWindow",
    "Headless OSMesa/EGL render window", 1, CreateHeadlessRenderWindow);
  this->RegisterOverride("vtkRenderWindowInteractor", "vtkDeepShadowHeadlessInteractor",
    "Interactor without an event loop: Start() renders and returns", 1, CreateHeadlessInteractor);
}

const char* vtkDeepShadowRenderingObjectFactory::GetVTKSourceVersion()
{
  return VTK_SOURCE_VERSION;
}

const char* vtkDeepShadowRenderingObjectFactory::GetDescription()
{
  return "vtkDeepShadow headless rendering factory";
}

bool vtkDeepShadowRenderingObjectFactory::ShouldOverrideRenderWindow()
{
  if (const char* forced = std::getenv("VTK_DEEPSHADOW_HEADLESS"))
  {
    if (std::strcmp(forced, "1") == 0)
    {
      return true;
    }
    if (std::strcmp(forced, "0") == 0)
    {
      return false;
    }
  }
  return !IsSet("DISPLAY") && !IsSet("WAYLAND_DISPLAY");
}

void vtkDeepShadowRenderingObjectFactory::RegisterIfHeadless()
{
  static bool registered = false;
  if (registered || !ShouldOverrideRenderWindow())
  {
    return;
  }
  registered = true;
  // Switch off every earlier vtkRenderWindow and interactor override (the X11 ones), then
  // ours on.
  vtkObjectFactory::SetAllEnableFlags(0, "vtkRenderWindow");
  vtkObjectFactory::SetAllEnableFlags(0, "vtkRenderWindowInteractor");
  auto* factory = vtkDeepShadowRenderingObjectFactory::New();
  vtkObjectFactory::RegisterFactory(factory);
  factory->Delete();
  vtkObjectFactory::SetAllEnableFlags(1, "vtkRenderWindow", "vtkDeepShadowRenderWindow");
  vtkObjectFactory::SetAllEnableFlags(1, "vtkRenderWindowInteractor", "vtkDeepShadowHeadlessInteractor");
}

void vtkDeepShadowRenderingObjectFactory::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Overrides vtkRenderWindow and vtkRenderWindowInteractor: "
     << (ShouldOverrideRenderWindow() ? "yes" : "no") << "\n";
}

// Called by VTK's module auto-initialisation (this module IMPLEMENTS VTK::RenderingCore).
VTKDEEPSHADOWRENDERING_EXPORT void vtkDeepShadowRendering_AutoInit_Construct()
{
  vtkDeepShadowRenderingObjectFactory::RegisterIfHeadless();
  vtkDeepShadowVolumeMapperFactory::OverrideFromEnvironment();
}

VTKDEEPSHADOWRENDERING_EXPORT void vtkDeepShadowRendering_AutoInit_Destruct() {}
