#include "vtkDeepShadowBrickExchange.h"

bool vtkDeepShadowBrickExchange::SendReceive(int, const std::vector<float>&, int, std::vector<float>&, bool, int)
{
  return false;
}

void vtkDeepShadowBrickExchange::BeginFrame()
{
  this->LastBytes = 0;
  this->LastMessages = 0;
  this->LastMilliseconds = 0.0;
  this->LastScanned = false;
}

void vtkDeepShadowBrickExchange::Account(long long bytes, int messages, double milliseconds)
{
  this->LastBytes += bytes;
  this->LastMessages += messages;
  this->LastMilliseconds += milliseconds;
}

void vtkDeepShadowBrickExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scan: " << this->Scan << "\n";
  os << indent << "LastBytes: " << this->LastBytes << "\n";
  os << indent << "LastMessages: " << this->LastMessages << "\n";
  os << indent << "LastMilliseconds: " << this->LastMilliseconds << "\n";
  os << indent << "LastScanned: " << this->LastScanned << "\n";
}
