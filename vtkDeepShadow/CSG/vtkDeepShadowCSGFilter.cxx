#include "vtkDeepShadowCSGFilter.h"

#include "CGALBoolean.h"
#include "Core/Bound/CSGExpression.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkDeepShadowCSGFilter);

vtkDeepShadowCSGFilter::vtkDeepShadowCSGFilter() = default;

vtkDeepShadowCSGFilter::~vtkDeepShadowCSGFilter() = default;

void vtkDeepShadowCSGFilter::SetExpression(const std::string& expression)
{
  if (this->Expression != expression)
  {
    this->Expression = expression;
    this->Modified();
  }
}

int vtkDeepShadowCSGFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (!this->Superclass::FillInputPortInformation(port, info))
  {
    return 0;
  }
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  // Optional so that RequestData runs and reports "no input" the filter's way.
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

void vtkDeepShadowCSGFilter::Fail(const std::string& message)
{
  this->LastError = message;
  vtkErrorMacro(<< message);
}

int vtkDeepShadowCSGFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  this->LastError.clear();
  this->RemovedDegenerateFaces = 0;
  this->ResultIsEmpty = false;
  this->LastMilliseconds = 0.0;
  this->LastOperations = 0;
  this->LastTriangleWork = 0.0;

  const int count = inputVector[0]->GetNumberOfInformationObjects();
  if (count == 0)
  {
    this->Fail("no input: connect at least one closed bound to input port 0");
    return 0;
  }
  std::vector<vtkPolyData*> bounds(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i)
  {
    bounds[static_cast<size_t>(i)] = vtkPolyData::GetData(inputVector[0], i);
  }

  deepshadow::CSGExpression expression;
  std::string error;
  if (!deepshadow::CSGExpression::Parse(this->Expression, count, expression, error))
  {
    this->Fail(error);
    return 0;
  }

  // Bounded before CGAL starts: each operation's corefinement takes time in its operands'
  // triangles, and an expression may name a bound any number of times.
  std::vector<double> leafTriangles;
  for (vtkPolyData* bound : bounds)
  {
    double triangles = 0.0;
    if (bound)
    {
      for (vtkCellArray* cells : { bound->GetPolys(), bound->GetStrips() })
      {
        triangles += static_cast<double>(cells->GetNumberOfConnectivityIds()) -
          2.0 * static_cast<double>(cells->GetNumberOfCells());
      }
    }
    leafTriangles.push_back(std::max(triangles, 0.0));
  }
  this->LastTriangleWork = expression.Root().TriangleWork(leafTriangles);
  if (this->MaximumTriangleWork > 0.0 && this->LastTriangleWork > this->MaximumTriangleWork)
  {
    std::ostringstream message;
    message << "the expression " << expression.ToString().substr(0, 60)
            << " would take CGAL about " << this->LastTriangleWork << " triangles of work (its "
            << "operations' operands, summed), more than the limit of " << this->MaximumTriangleWork
            << " (7 to 130 s a million here; SetMaximumTriangleWork, the tool's --csg-max-work)";
    this->Fail(message.str());
    return 0;
  }

  deepshadow::csg::EvaluationResult result;
  const auto start = std::chrono::steady_clock::now();
  const bool valid = deepshadow::csg::Evaluate(expression.Root(), bounds, output, result,
    [this](double fraction)
    {
      this->UpdateProgress(fraction);
      return !this->GetAbortExecute();
    });
  this->LastMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  this->RemovedDegenerateFaces = result.RemovedDegenerateFaces;
  this->LastOperations = result.Operations;

  for (const std::string& warning : result.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (!valid)
  {
    output->Initialize();
    this->Fail(result.Error);
    return 0;
  }
  this->ResultIsEmpty = result.Empty;
  if (result.Empty)
  {
    vtkWarningMacro(<< "the CSG result is empty (" << expression.ToString() << ")");
  }
  return 1;
}

void vtkDeepShadowCSGFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumTriangleWork: " << this->MaximumTriangleWork << "\n";
  os << indent << "LastTriangleWork: " << this->LastTriangleWork << "\n";
  os << indent << "Expression: " << (this->Expression.empty() ? "(union of all inputs)" : this->Expression)
     << "\n";
  os << indent << "LastError: " << (this->LastError.empty() ? "(none)" : this->LastError) << "\n";
  os << indent << "RemovedDegenerateFaces: " << this->RemovedDegenerateFaces << "\n";
  os << indent << "ResultIsEmpty: " << (this->ResultIsEmpty ? "true" : "false") << "\n";
  os << indent << "LastMilliseconds: " << this->LastMilliseconds << "\n";
  os << indent << "LastOperations: " << this->LastOperations << "\n";
}
