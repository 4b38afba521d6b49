// Writes the representation's proxy XML from its template with the ShadowTechnique list taken
// from the technique registry (deepshadow::ShadowTechniqueNames()), so that a new technique
// reaches ParaView's menu without an edit here. Run at build time:
//   TechniqueListXml TEMPLATE.xml.in OUTPUT.xml
// The line holding @SHADOW_TECHNIQUE_LIST@ becomes one <String value="NAME" /> per name, at
// that line's indentation. The output is rewritten only when it changes.
#include "Core/ShadowTechniques.h"

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: TechniqueListXml TEMPLATE OUTPUT\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in)
  {
    std::cerr << "TechniqueListXml: cannot read " << argv[1] << "\n";
    return 2;
  }
  const std::string tag = "@SHADOW_TECHNIQUE_LIST@";
  std::ostringstream out;
  std::string line;
  int replaced = 0;
  while (std::getline(in, line))
  {
    const std::size_t at = line.find(tag);
    if (at == std::string::npos)
    {
      out << line << "\n";
      continue;
    }
    const std::string indent = line.substr(0, line.find_first_not_of(" \t"));
    for (const std::string& name : deepshadow::ShadowTechniqueNames())
    {
      out << indent << "<String value=\"" << name << "\" />\n";
    }
    ++replaced;
  }
  if (replaced != 1)
  {
    std::cerr << "TechniqueListXml: " << argv[1] << " must hold " << tag << " once\n";
    return 2;
  }
  std::ifstream old(argv[2]);
  std::ostringstream oldText;
  oldText << old.rdbuf();
  if (old && oldText.str() == out.str())
  {
    return 0;
  }
  std::ofstream write(argv[2]);
  write << out.str();
  if (!write)
  {
    std::cerr << "TechniqueListXml: cannot write " << argv[2] << "\n";
    return 2;
  }
  return 0;
}
