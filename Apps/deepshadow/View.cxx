// deepshadow view: the scene in a window on a display (VTK's own X11 window with our mapper).
// The mouse orbits the camera; Ctrl + left drag moves the key light; keys switch the
// technique, move the light, change epsilon and the map size, toggle the ground; a line at the
// bottom shows the technique, the frame time and the shadow memory. --keys feeds keys without
// a person (then --screenshots DIR keeps a picture and the statistics after each 's').
#include "Commands.h"
#include "Display.h"

#include "Json.h"
#include "SceneSetup.h"

#include "Core/ShadowTechniques.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkObjectFactory.h"
#include "vtkMath.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransform.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace deepshadow
{
namespace tool
{
namespace
{
class Viewer
{
public:
  Viewer(const Options& options)
    : Settings(options)
    , Scene(SceneSetup::Build(options))
  {
    // t cycles through the techniques as they are (no "-cached" variants), and none.
    this->Names = { "none" };
    for (const std::string& name : ShadowTechniqueNames())
    {
      if (name.size() < 7 || name.compare(name.size() - 7, 7, "-cached") != 0)
      {
        this->Names.push_back(name);
      }
    }
    const auto at = std::find(this->Names.begin(), this->Names.end(), options.Technique);
    this->Index = at == this->Names.end() ? 0 : static_cast<size_t>(at - this->Names.begin());
    // The scene's renderer moves into VTK's own window for the display.
    this->Scene.Window->RemoveRenderer(this->Scene.Renderer);
    this->Window = vtkSmartPointer<vtkRenderWindow>::New();
    this->Window->AddRenderer(this->Scene.Renderer);
    this->Window->SetSize(options.Width, options.Height);
    this->Window->SetWindowName(("deepshadow view: " + this->Scene.Name).c_str());
    this->Text->GetTextProperty()->SetFontSize(12);
    this->Text->GetTextProperty()->SetColor(0.9, 0.9, 0.9);
    this->Text->SetDisplayPosition(8, 8);
    // The status line in a renderer of its own, drawn after the scene's in the same frame:
    // it shows the figures of the frame beneath it, whoever asked for the frame (a key, or
    // the interactor turning the camera).
    this->Window->SetNumberOfLayers(2);
    this->Overlay->SetLayer(1);
    this->Overlay->InteractiveOff();
    this->Overlay->AddActor2D(this->Text);
    this->Window->AddRenderer(this->Overlay);
    this->Scene.Renderer->AddObserver(vtkCommand::StartEvent, this, &Viewer::SceneStarted);
    this->Scene.Renderer->AddObserver(vtkCommand::EndEvent, this, &Viewer::SceneDrawn);
    this->Overlay->AddObserver(vtkCommand::StartEvent, this, &Viewer::ShowStatus);
    this->Key = vtkLight::SafeDownCast(this->Scene.Renderer->GetLights()->GetItemAsObject(0));
  }

  vtkRenderWindow* GetWindow() { return this->Window; }
  vtkLight* GetKeyLight() { return this->Key; }

  /** Renders a frame; its status line shows that frame's time, memory and builds. */
  void Render() { this->Window->Render(); }

  // The scene's renderer times its frame (GL finished); the overlay, drawn next, shows it.
  void SceneStarted() { this->SceneStart = std::chrono::steady_clock::now(); }
  void SceneDrawn()
  {
    this->Window->WaitForCompletion();
    this->FrameMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - this->SceneStart).count();
  }
  void ShowStatus() { this->Text->SetInput(this->Status().c_str()); }

  std::string Status() const
  {
    vtkDeepShadowTechnique* technique = this->Scene.Mapper->GetShadowTechnique();
    std::ostringstream line;
    line << this->Names[this->Index];
    if (auto* dsm = vtkDeepShadowDeepShadowMapTechnique::SafeDownCast(technique))
    {
      line << " (epsilon " << dsm->GetEpsilon() << ")";
    }
    if (auto* map = vtkDeepShadowLightSpaceTechnique::SafeDownCast(technique))
    {
      line << " map " << map->GetMapSize();
    }
    char numbers[128];
    std::snprintf(numbers, sizeof(numbers), " | %.0f ms | shadows %.1f MiB | builds %d",
      this->FrameMs, technique ? technique->GetShadowBytes() / 1048576.0 : 0.0,
      this->Scene.Mapper->GetShadowBuilds());
    line << numbers << "\nt technique   arrows, Ctrl+drag: light   e/E epsilon   m/M map size"
         << "\ng meshes   s screenshot   q quit";
    return line.str();
  }

  /** Applies one key (VTK key symbol); false if it means nothing here. */
  bool Press(const std::string& key)
  {
    vtkDeepShadowTechnique* technique = this->Scene.Mapper->GetShadowTechnique();
    if (key == "t")
    {
      this->Index = (this->Index + 1) % this->Names.size();
      const std::string& name = this->Names[this->Index];
      this->Scene.Mapper->SetShadowTechnique(name == "none" ? nullptr : vtkDeepShadowTechniqueFactory::New(name));
    }
    else if (key == "Left" || key == "Right" || key == "Up" || key == "Down")
    {
      this->MoveLight(key == "Left" ? -10.0 : key == "Right" ? 10.0 : 0.0,
        key == "Up" ? 10.0 : key == "Down" ? -10.0 : 0.0);
    }
    else if ((key == "e" || key == "E") && vtkDeepShadowDeepShadowMapTechnique::SafeDownCast(technique))
    {
      auto* dsm = vtkDeepShadowDeepShadowMapTechnique::SafeDownCast(technique);
      dsm->SetEpsilon(dsm->GetEpsilon() * (key == "e" ? 0.5 : 2.0));
    }
    else if ((key == "m" || key == "M") && vtkDeepShadowLightSpaceTechnique::SafeDownCast(technique))
    {
      auto* map = vtkDeepShadowLightSpaceTechnique::SafeDownCast(technique);
      map->SetMapSize(key == "m" ? map->GetMapSize() / 2 : map->GetMapSize() * 2);
    }
    else if (key == "g")
    {
      vtkActorCollection* actors = this->Scene.Renderer->GetActors();
      actors->InitTraversal();
      while (vtkActor* actor = actors->GetNextActor())
      {
        actor->SetVisibility(!actor->GetVisibility());
      }
    }
    else
    {
      return false;
    }
    return true;
  }

  /** Turns the key light about the focal point: `azimuth` about the view-up, `elevation`
   * about the camera's right (degrees). */
  void MoveLight(double azimuth, double elevation)
  {
    if (!this->Key)
    {
      return;
    }
    vtkCamera* camera = this->Scene.Renderer->GetActiveCamera();
    const double* focal = this->Key->GetFocalPoint();
    double right[3], up[3], forward[3];
    camera->GetViewUp(up);
    camera->GetDirectionOfProjection(forward);
    vtkMath::Cross(forward, up, right);
    vtkNew<vtkTransform> turn;
    turn->Translate(focal[0], focal[1], focal[2]);
    turn->RotateWXYZ(azimuth, up);
    turn->RotateWXYZ(elevation, right);
    turn->Translate(-focal[0], -focal[1], -focal[2]);
    double position[3];
    this->Key->GetPosition(position);
    turn->TransformPoint(position, position);
    this->Key->SetPosition(position);
  }

  /**
   * DIR/view-N-window.png (the window as seen), DIR/view-N.png (the picture alone, for
   * comparisons) and DIR/view-N.json (the status).
   */
  void Screenshot(const std::string& directory)
  {
    const std::string stem = directory + "/view-" + std::to_string(++this->Shots);
    for (const bool status : { true, false })
    {
      this->Text->SetVisibility(status);
      this->Window->Render();
      vtkNew<vtkWindowToImageFilter> grab;
      grab->SetInput(this->Window);
      grab->ReadFrontBufferOff();
      vtkNew<vtkPNGWriter> writer;
      writer->SetInputConnection(grab->GetOutputPort());
      writer->SetFileName((stem + (status ? "-window.png" : ".png")).c_str());
      writer->Write();
    }
    this->Text->SetVisibility(true);
    vtkDeepShadowTechnique* technique = this->Scene.Mapper->GetShadowTechnique();
    Json stats;
    stats.Set("technique", this->Names[this->Index])
      .Set("frame_ms", this->FrameMs)
      .Set("shadow_builds", this->Scene.Mapper->GetShadowBuilds())
      .Set("shadow_bytes", technique ? technique->GetShadowBytes() : 0LL)
      .Set("window", this->Window->GetClassName())
      .Set("status", this->Status());
    stats.Write(stem + ".json");
  }

private:
  Options Settings;
  SceneSetup Scene;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkTextActor> Text;
  vtkNew<vtkRenderer> Overlay; // layer 1: the status line over the scene
  std::chrono::steady_clock::time_point SceneStart;
  vtkLight* Key = nullptr;
  std::vector<std::string> Names;
  size_t Index = 0;
  double FrameMs = 0.0;
  int Shots = 0;
};

// The trackball, except that Ctrl + left drag turns the key light instead of the camera.
class LightDragStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static LightDragStyle* New();
  vtkTypeMacro(LightDragStyle, vtkInteractorStyleTrackballCamera);
  Viewer* View = nullptr;

  void OnLeftButtonDown() override
  {
    this->Dragging = this->Interactor->GetControlKey() != 0;
    if (!this->Dragging)
    {
      this->Superclass::OnLeftButtonDown();
    }
  }
  void OnLeftButtonUp() override
  {
    this->Dragging = false;
    this->Superclass::OnLeftButtonUp();
  }
  void OnMouseMove() override
  {
    if (!this->Dragging)
    {
      this->Superclass::OnMouseMove();
      return;
    }
    const int* now = this->Interactor->GetEventPosition();
    const int* before = this->Interactor->GetLastEventPosition();
    this->View->MoveLight(0.5 * (now[0] - before[0]), 0.5 * (now[1] - before[1]));
    this->View->Render();
  }
  void OnChar() override {} // VTK's own keys (wireframe, stereo, ...) are not ours

private:
  bool Dragging = false;
};
vtkStandardNewMacro(LightDragStyle);

struct KeyContext
{
  Viewer* View;
  std::string ScreenshotDir;
};

void OnKey(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* interactor = static_cast<vtkRenderWindowInteractor*>(caller);
  auto* context = static_cast<KeyContext*>(clientData);
  const std::string key = interactor->GetKeySym() ? interactor->GetKeySym() : "";
  if (key == "q" || key == "Escape")
  {
    interactor->TerminateApp();
    return;
  }
  if (key == "s")
  {
    context->View->Screenshot(context->ScreenshotDir.empty() ? "." : context->ScreenshotDir);
    return;
  }
  if (context->View->Press(key))
  {
    context->View->Render();
  }
}
}

bool ParseViewerOption(Options& o, const std::string& key, const std::function<std::string()>& next)
{
  if (key == "--keys")
  {
    o.ViewKeys = next();
    std::stringstream keys(o.ViewKeys);
    std::string one;
    while (std::getline(keys, one, ','))
    {
      static const char* const known[] = { "t", "Left", "Right", "Up", "Down", "e", "E", "m",
        "M", "g", "s" };
      if (std::none_of(std::begin(known), std::end(known), [&](const char* k) { return one == k; }))
      {
        throw UsageError("--keys takes t, Left, Right, Up, Down, e, E, m, M, g and s, "
                         "comma-separated; not '" + one + "'");
      }
    }
  }
  else if (key == "--screenshots")
  {
    o.ScreenshotDir = next();
  }
  else
  {
    return false;
  }
  return true;
}

int RunView(const Options& options)
{
  // VTK 9.1's window here is X11's: without an X server answering at DISPLAY it crashes.
  const char* display = std::getenv("DISPLAY");
  if (!(display && *display))
  {
    throw UsageError("view needs a display and none is set (DISPLAY); render writes pictures "
                     "without one");
  }
  if (!DisplayAnswers())
  {
    throw UsageError(std::string("view cannot open the display DISPLAY=") + display +
      " (no X server answers there); render writes pictures without one");
  }
  Viewer view(options);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(view.GetWindow());
  vtkNew<LightDragStyle> style;
  style->View = &view;
  interactor->SetInteractorStyle(style);
  KeyContext context{ &view, options.ScreenshotDir };
  vtkNew<vtkCallbackCommand> onKey;
  onKey->SetCallback(OnKey);
  onKey->SetClientData(&context);
  interactor->AddObserver(vtkCommand::KeyPressEvent, onKey);
  interactor->Initialize();
  view.Render();

  if (options.ViewKeys.empty())
  {
    interactor->Start();
    return 0;
  }
  // Keys without a person: each goes through the interactor as a key press would.
  std::stringstream keys(options.ViewKeys);
  std::string key;
  while (std::getline(keys, key, ','))
  {
    interactor->SetKeySym(key.c_str());
    interactor->SetKeyCode(key.size() == 1 ? key[0] : 0);
    interactor->InvokeEvent(vtkCommand::KeyPressEvent, nullptr);
  }
  return 0;
}

}
}
