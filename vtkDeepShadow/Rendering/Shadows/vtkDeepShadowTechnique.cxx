#include "vtkDeepShadowTechnique.h"

#include "OpticalModel.h"
#include "Shadows.h"
#include "ShadowContext.h"

#include "GL/ComputeProgram.h"
#include "ShaderComposer.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <set>

namespace
{
double NowMilliseconds()
{
  return std::chrono::duration<double, std::milli>(
    std::chrono::steady_clock::now().time_since_epoch()).count();
}
}

// The feeler's opacity table: the transfer function's opacity corrected for the feeler step.
class vtkDeepShadowTechnique::FeelerTable
{
public:
  vtkSmartPointer<vtkTextureObject> Texture;
  std::array<double, 7> Key{ {} };
};

vtkDeepShadowTechnique::vtkDeepShadowTechnique()
  : Feeler(new FeelerTable)
{
}

vtkDeepShadowTechnique::~vtkDeepShadowTechnique() = default;

void vtkDeepShadowTechnique::SetStepFactor(double factor)
{
  const double clamped = std::clamp(factor, 0.01, 100.0);
  if (clamped != factor)
  {
    vtkWarningMacro("StepFactor " << factor << " is outside [0.01, 100]; using " << clamped);
  }
  if (clamped != this->StepFactor)
  {
    this->StepFactor = clamped;
    this->Modified();
  }
}

void vtkDeepShadowTechnique::SetThreshold(double threshold)
{
  const double clamped = std::clamp(threshold, 0.0, 1.0);
  if (clamped != threshold)
  {
    vtkWarningMacro("Threshold " << threshold << " is outside [0, 1]; using " << clamped);
  }
  if (clamped != this->Threshold)
  {
    this->Threshold = clamped;
    this->Modified();
  }
}

std::string vtkDeepShadowTechnique::GetName() const
{
  return this->GetParameters().Name();
}

long long vtkDeepShadowTechnique::GetShadowBytes() const
{
  const long long table =
    this->Feeler->Texture ? static_cast<long long>(this->Feeler->Texture->GetWidth()) * 16 : 0;
  return table + this->StructureBytes;
}

void vtkDeepShadowTechnique::FillParameters(deepshadow::ShadowParameters& parameters) const
{
  parameters.StepFactor = this->StepFactor;
  parameters.Threshold = this->Threshold;
  parameters.Mode = this->ThresholdMode == ScalarThreshold ? deepshadow::ThresholdMode::Scalar
                                                           : deepshadow::ThresholdMode::Opacity;
}

double vtkDeepShadowTechnique::FeelerStep(const deepshadow::ShadowContext& context) const
{
  return this->StepFactor * context.ViewStep;
}

bool vtkDeepShadowTechnique::Prepare(deepshadow::ShadowContext& context)
{
  const double step = this->FeelerStep(context);
  const std::array<double, 7> key{ { static_cast<double>(context.DataVersion),
    context.OpacityVersion, context.Transfer.OpacityUnitDistance, step,
    static_cast<double>(context.TableSize), context.Range.x, context.Range.y } };
  if (!this->Feeler->Texture || key != this->Feeler->Key)
  {
    const deepshadow::TransferTable table = deepshadow::TransferTable::Sample(
      context.Transfer, context.Range.x, context.Range.y, context.TableSize, step);
    if (this->Feeler->Texture)
    {
      this->Feeler->Texture->ReleaseGraphicsResources(context.Window);
    }
    this->Feeler->Texture = vtkSmartPointer<vtkTextureObject>::New();
    this->Feeler->Texture->SetContext(context.Window);
    this->Feeler->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Feeler->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Feeler->Texture->SetMinificationFilter(vtkTextureObject::Linear);
    this->Feeler->Texture->SetMagnificationFilter(vtkTextureObject::Linear);
    this->Feeler->Texture->Create2DFromRaw(table.Size, 1, 4, VTK_FLOAT,
      const_cast<float*>(table.RGBA.data()));
    this->Feeler->Key = key;
  }
  this->LastError.clear();
  return true;
}

void vtkDeepShadowTechnique::ActivateFeelerTable()
{
  this->Feeler->Texture->Activate();
}

void vtkDeepShadowTechnique::DeactivateFeelerTable()
{
  if (this->Feeler->Texture)
  {
    this->Feeler->Texture->Deactivate();
  }
}

void vtkDeepShadowTechnique::SetFeelerUniforms(deepshadow::UniformSink& sink,
  const deepshadow::ShadowContext& context, bool skipEmpty) const
{
  const double step = this->FeelerStep(context);
  const bool onScalar = this->ThresholdMode == ScalarThreshold;
  const deepshadow::ShadowParameters parameters = this->GetParameters();
  sink.Set("u_feelerTable", this->Feeler->Texture->GetTextureUnit());
  sink.Set("u_feelerStep", static_cast<float>(step));
  // Opacity thresholds are compared with the table's step-corrected opacity.
  sink.Set("u_feelerThreshold",
    static_cast<float>(onScalar
        ? this->Threshold
        : deepshadow::CorrectOpacity(this->Threshold, step, context.Transfer.OpacityUnitDistance)));
  sink.Set("u_feelerThresholdOnScalar", onScalar ? 1 : 0);
  sink.Set("u_scalarRange", glm::vec2(context.Range));
  sink.Set("u_feelerTermination",
    parameters.EarlyTermination ? static_cast<float>(deepshadow::ShadowTerminationTransmittance) : 0.0f);
  // Zero-opacity blocks cannot stop a feeler, unless the threshold is on the scalar.
  const bool opaqueOnScalar = onScalar && (parameters.Opaque || parameters.Kind == deepshadow::ShadowKind::ShadowMap);
  if (context.Occupancy)
  {
    sink.Set("u_feelerSkipEmpty", skipEmpty && !opaqueOnScalar ? 1 : 0);
  }
}

bool vtkDeepShadowTechnique::BeginBuildPass(deepshadow::ComputeProgram& program,
  const char* shaderTemplate, const deepshadow::ShadowContext& context)
{
  std::set<std::string> features{ "VolumeSampling", "Feeler" };
  if (context.Occupancy)
  {
    features.insert("EmptySpace");
  }
  if (!program.Build(deepshadow::ComposeShader(shaderTemplate, features)))
  {
    this->LastError = program.Error();
    return false;
  }
  this->BuildStart = NowMilliseconds();
  context.Volume->Activate();
  if (context.Occupancy)
  {
    context.Occupancy->Activate();
  }
  this->ActivateFeelerTable();
  program.Use();
  deepshadow::UniformSink sink(&program);
  context.SetVolumeUniforms(sink);
  this->SetFeelerUniforms(sink, context, true);
  return true;
}

void vtkDeepShadowTechnique::EndBuildPass(const deepshadow::ShadowContext& context, int count)
{
  glFinish(); // the build time includes the GPU's work
  this->DeactivateFeelerTable();
  context.Volume->Deactivate();
  if (context.Occupancy)
  {
    context.Occupancy->Deactivate();
  }
  // VTK tracks the bound program; ours replaced it.
  context.Window->GetShaderCache()->ReleaseCurrentShader();
  this->BuildCount += count;
  this->LastBuildMilliseconds = NowMilliseconds() - this->BuildStart;
}

void vtkDeepShadowTechnique::Bind(deepshadow::UniformSink&, const deepshadow::ShadowContext&) {}

void vtkDeepShadowTechnique::Unbind()
{
  this->DeactivateFeelerTable();
}

void vtkDeepShadowTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Feeler->Texture)
  {
    this->Feeler->Texture->ReleaseGraphicsResources(window);
    this->Feeler->Texture = nullptr;
  }
}

void vtkDeepShadowTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Technique: " << this->GetName() << "\n";
  os << indent << "StepFactor: " << this->StepFactor << "\n";
  os << indent << "Threshold: " << this->Threshold
     << (this->ThresholdMode == ScalarThreshold ? " (scalar)" : " (opacity)") << "\n";
  os << indent << "BuildCount: " << this->BuildCount << "\n";
  os << indent << "ShadowBytes: " << this->GetShadowBytes() << "\n";
}
