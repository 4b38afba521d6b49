#include "ReaderMessages.h"

#include "vtkAlgorithm.h"
#include "vtkExecutive.h"
#include "vtkObject.h"
#include "vtkXMLReader.h"

#include <iostream>

namespace deepshadow
{
namespace reader
{

std::string OneLine(const char* message)
{
  std::string text = message ? message : "";
  if (text.compare(0, 6, "ERROR:") == 0 || text.compare(0, 8, "Warning:") == 0)
  {
    const size_t eol = text.find('\n');
    text = eol == std::string::npos ? text : text.substr(eol + 1);
  }
  const size_t prefix = text.find("): ");
  if (prefix != std::string::npos && prefix < text.find('\n'))
  {
    text = text.substr(prefix + 3);
  }
  for (char& c : text)
  {
    c = (c == '\n' || c == '\r') ? ' ' : c;
  }
  const size_t first = text.find_first_not_of(' ');
  const size_t last = text.find_last_not_of(" .");
  return last == std::string::npos ? std::string() : text.substr(first, last + 1 - first);
}

void ErrorCollector::Execute(vtkObject* caller, unsigned long event, void* callData)
{
  const std::string text = OneLine(static_cast<const char*>(callData));
  if (event == vtkCommand::WarningEvent)
  {
    this->Warnings.push_back(text);
  }
  else if (vtkExecutive::SafeDownCast(caller))
  {
    // "Algorithm ... returned failure for request: <dump>": the delegate's own message, if
    // any, came first and says more.
    this->ExecutiveFailed = true;
  }
  else
  {
    this->Errors.push_back(text);
  }
}

void ErrorCollector::Watch(vtkAlgorithm* reader)
{
  reader->AddObserver(vtkCommand::ErrorEvent, this);
  reader->AddObserver(vtkCommand::WarningEvent, this);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this);
  if (auto* xml = vtkXMLReader::SafeDownCast(reader))
  {
    xml->SetReaderErrorObserver(this);
    xml->SetParserErrorObserver(this);
  }
}

void ErrorCollector::Clear()
{
  this->Errors.clear();
  this->Warnings.clear();
  this->ExecutiveFailed = false;
}

std::string ErrorCollector::Reason(const std::string& fallback) const
{
  return this->Errors.empty() ? fallback : this->Errors.front();
}

WarningDisplayOn::WarningDisplayOn()
  : Saved(vtkObject::GetGlobalWarningDisplay())
{
  vtkObject::GlobalWarningDisplayOn();
}

WarningDisplayOn::~WarningDisplayOn()
{
  vtkObject::SetGlobalWarningDisplay(this->Saved);
}

CerrCapture::CerrCapture()
  : Saved(std::cerr.rdbuf(this->Text.rdbuf()))
{
}

CerrCapture::~CerrCapture()
{
  std::cerr.rdbuf(this->Saved);
}

std::vector<std::string> CerrCapture::Lines() const
{
  std::vector<std::string> lines;
  std::istringstream in(this->Text.str());
  std::string line;
  while (std::getline(in, line))
  {
    line = OneLine(line.c_str());
    if (!line.empty())
    {
      lines.push_back(line);
    }
  }
  return lines;
}

}
}
