#include "PageAnalysis.h"

#include "GL/GLObjects.h"
#include "GL/UniformSink.h"
#include "ShaderComposer.h"
#include "Sampling/ShadowContext.h"
#include "vtkDeepShadowLightSpaceCS.h"
#include "vtkDeepShadowPageRequestsCS.h"
#include "vtkDeepShadowShadowMapBuild.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include <algorithm>
#include <map>

namespace deepshadow
{
namespace
{
int NextPowerOfTwo(long long n)
{
  int p = 1;
  while (p < n)
  {
    p <<= 1;
  }
  return p;
}
}

glm::ivec2 PageAnalysis::AnalysisSize(const ShadowContext& context, int downsample) const
{
  const glm::ivec2 viewport(context.View.GetWidth(), context.View.GetHeight());
  return (viewport + downsample - 1) / downsample;
}

bool PageAnalysis::Analyse(vtkDeepShadowTechnique* technique, const ShadowContext& context, const SlotFaces& faces,
  int facesPerLight, const PageLayout& layout, int downsample, std::vector<std::uint32_t>& unique,
  std::string& error)
{
  if (!this->FindReceivers(technique, context, downsample, error) || !this->BuildStages(faces, error))
  {
    return false;
  }
  const unsigned int listed = this->ListRequests(context, faces, facesPerLight, layout, downsample);
  this->Last.Requested = this->SortUnique(listed, unique);
  context.Window->GetShaderCache()->ReleaseCurrentShader();
  this->Last.AfterComponents = listed;
  return true;
}

bool PageAnalysis::FindReceivers(
  vtkDeepShadowTechnique* technique, const ShadowContext& context, int downsample, std::string& error)
{
  const glm::ivec2 viewport(context.View.GetWidth(), context.View.GetHeight());
  const glm::ivec2 size = this->AnalysisSize(context, downsample);
  if (!this->Hits || this->HitsSize != size)
  {
    DeleteTexture(this->Hits);
    this->Hits = NewArrayTexture(context.Window, GL_R32F, size.x, size.y, 1);
    this->HitsSize = size;
  }
  if (!vtkDeepShadowTechnique::Internals::BeginBuildPass(technique, this->Receivers, vtkDeepShadowLightSpaceCS, context, "Build",
        "//@Dec\n#define LIGHT_SPACE_CAMERA\n" + std::string(vtkDeepShadowShadowMapBuild)))
  {
    error = technique->GetLastError();
    return false;
  }
  this->Receivers.Set("u_inverseViewProjection", glm::mat4(context.View.GetInverseViewProjection()));
  this->Receivers.Set("u_viewport", glm::vec2(viewport));
  this->Receivers.Set("u_downsample", downsample);
  this->Receivers.Set("u_analysisSize", size);
  this->Receivers.Set("u_layer", 0);
  this->Receivers.Set("u_deferredPass", 0);
  glBindImageTexture(0, this->Hits, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  this->Receivers.Dispatch(glm::ivec3(size, 1), glm::ivec3(8, 8, 1));
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  vtkDeepShadowTechnique::Internals::EndBuildPass(technique, context);
  return true;
}

bool PageAnalysis::BuildStages(const SlotFaces& faces, std::string& error)
{
  std::map<std::string, ShaderFeature> runtime;
  runtime["Locate"] = ShaderFeature(
    "Locate", "//@Dec\n#define LIGHT_SPACE_LOCATE_ONLY\n" + LightSpaceSource(faces));
  const std::string composed = ComposeShader(vtkDeepShadowPageRequestsCS, {}, runtime);
  const size_t version = composed.find('\n') + 1;
  for (int stage = 0; stage < 4; ++stage)
  {
    std::string source = composed;
    source.insert(version, "#define PAGE_STAGE " + std::to_string(stage) + "\n");
    if (!this->Stages[stage].Build(source))
    {
      error = this->Stages[stage].Error();
      return false;
    }
  }
  return true;
}

unsigned int PageAnalysis::ListRequests(const ShadowContext& context, const SlotFaces& faces,
  int facesPerLight, const PageLayout& layout, int downsample)
{
  const glm::ivec2 viewport(context.View.GetWidth(), context.View.GetHeight());
  const glm::ivec2 size = this->AnalysisSize(context, downsample);
  const long long requests = static_cast<long long>(size.x) * size.y * static_cast<int>(faces.size());
  const int padded = NextPowerOfTwo(static_cast<int>(std::max<long long>(requests, 2)));
  EnsureStorageBuffer(this->Requests, this->RequestsBytes, 4 * requests);
  EnsureStorageBuffer(this->List, this->ListBytes, 4 * (1 + static_cast<long long>(padded)));
  EnsureStorageBuffer(this->Unique, this->UniqueBytes, 4 * (2 + requests));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->Requests);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->List);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, this->Unique);
  const GLuint zeros[2] = { 0, 0 };
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Unique);
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(zeros), zeros);
  // The list's keys beyond its count sort last.
  const GLuint noPage = NoPage;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->List);
  glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &noPage);
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), zeros);

  ComputeProgram& requestPass = this->Stages[0];
  requestPass.Use();
  UniformSink sink(&requestPass);
  SetLightSpaceFaceUniforms(
    sink, faces, static_cast<float>(layout.MaxResolution), facesPerLight, 1);
  vtkTextureUnitManager* units = context.Window->GetTextureUnitManager();
  const int unit = units->Allocate();
  context.Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, this->Hits);
  requestPass.Set("u_hits", unit);
  requestPass.Set("u_inverseViewProjection", glm::mat4(context.View.GetInverseViewProjection()));
  requestPass.Set("u_viewport", glm::vec2(viewport));
  requestPass.Set("u_downsample", downsample);
  requestPass.Set("u_analysisSize", size);
  requestPass.Set("u_pageSize", layout.PageSize);
  requestPass.Set("u_finestLevel", layout.FinestLevel());
  requestPass.Set("u_baseLevel", layout.BaseLevel());
  requestPass.Dispatch(glm::ivec3(size, 1), glm::ivec3(8, 8, 1));
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  units->Free(unit);

  this->Stages[1].Use();
  this->Stages[1].Set("u_analysisSize", size);
  this->Stages[1].Dispatch(glm::ivec3(size, static_cast<int>(faces.size())), glm::ivec3(8, 8, 1));
  GLuint listed = 0;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->List);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(listed), &listed);
  return listed;
}

long long PageAnalysis::SortUnique(unsigned int listed, std::vector<std::uint32_t>& unique)
{
  // Bitonic sort of the listed requests, padded with NoPage to a power of two.
  const int length = NextPowerOfTwo(static_cast<int>(std::max<GLuint>(listed, 2)));
  this->Stages[2].Use();
  this->Stages[2].Set("u_length", length);
  for (int k = 2; k <= length; k <<= 1)
  {
    for (int j = k >> 1; j > 0; j >>= 1)
    {
      this->Stages[2].Set("u_k", k);
      this->Stages[2].Set("u_j", j);
      this->Stages[2].Dispatch(glm::ivec3(length, 1, 1), glm::ivec3(64, 1, 1));
    }
  }
  if (listed > 0)
  {
    this->Stages[3].Use();
    this->Stages[3].Dispatch(glm::ivec3(static_cast<int>(listed), 1, 1), glm::ivec3(64, 1, 1));
  }
  GLuint header[2] = { 0, 0 };
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Unique);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(header), header);
  unique.assign(header[0], 0u);
  if (header[0] > 0)
  {
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, sizeof(header), 4 * static_cast<GLsizeiptr>(header[0]), unique.data());
  }
  for (int binding = 0; binding < 3; ++binding)
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  // The unique pass appends in any order.
  std::sort(unique.begin(), unique.end());
  return header[1];
}

void PageAnalysis::Release()
{
  DeleteTexture(this->Hits);
  this->HitsSize = glm::ivec2(0);
  DeleteBuffer(this->Requests, this->RequestsBytes);
  DeleteBuffer(this->List, this->ListBytes);
  DeleteBuffer(this->Unique, this->UniqueBytes);
  this->Receivers.Release();
  for (ComputeProgram& stage : this->Stages)
  {
    stage.Release();
  }
}
}
