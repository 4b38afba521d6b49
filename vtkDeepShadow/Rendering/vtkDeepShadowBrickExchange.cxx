#include "vtkDeepShadowBrickExchange.h"

void vtkDeepShadowBrickExchange::BeginFrame()
{
  this->LastBytes = 0;
  this->LastMilliseconds = 0.0;
}

void vtkDeepShadowBrickExchange::Account(long long bytes, double milliseconds)
{
  this->LastBytes += bytes;
  this->LastMilliseconds += milliseconds;
}

void vtkDeepShadowBrickExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastBytes: " << this->LastBytes << "\n";
  os << indent << "LastMilliseconds: " << this->LastMilliseconds << "\n";
}
