#include "vtkDeepShadowHeadlessInteractor.h"

#include "vtkDeepShadowImageConversion.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"

#include <cstdlib>

vtkStandardNewMacro(vtkDeepShadowHeadlessInteractor);

void vtkDeepShadowHeadlessInteractor::Start()
{
  ++this->Starts;
  // As VTK's Start(): a compositing observer may run the loop instead.
  if (this->HasObserver(vtkCommand::StartEvent) && !this->HandleEventLoop)
  {
    this->InvokeEvent(vtkCommand::StartEvent, nullptr);
    return;
  }
  if (!this->Initialized)
  {
    this->Initialize(); // renders
  }
  else if (this->RenderWindow)
  {
    this->Render();
  }
  const char* screenshot = std::getenv("VTK_DEEPSHADOW_SCREENSHOT");
  if (screenshot && *screenshot && this->RenderWindow)
  {
    if (!deepshadow::WritePNG(deepshadow::CaptureWindow(this->RenderWindow), screenshot))
    {
      vtkErrorMacro("VTK_DEEPSHADOW_SCREENSHOT: cannot write " << screenshot);
    }
  }
}

void vtkDeepShadowHeadlessInteractor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Starts: " << this->Starts << "\n";
}
