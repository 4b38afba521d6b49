// Internal: choice of headless backend.
#include "HeadlessContext.h"

namespace deepshadow
{
namespace headless
{

const char* BackendName(Backend backend)
{
  switch (backend)
  {
    case Backend::OSMesa:
      return "osmesa";
    case Backend::EGL:
      return "egl";
    case Backend::None:
      break;
  }
  return "none";
}

std::unique_ptr<HeadlessContext> HeadlessContext::Create(Backend backend, std::string& error)
{
  switch (backend)
  {
    case Backend::OSMesa:
      return CreateOSMesaContext(error);
    case Backend::EGL:
      return CreateEGLContext(error);
    case Backend::None:
      break;
  }
  error = "no headless backend was chosen";
  return nullptr;
}

}
}
