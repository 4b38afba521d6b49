#include "Core/ShadowParameterText.h"

#include <sstream>
#include <stdexcept>

namespace deepshadow
{

std::vector<std::pair<std::string, std::string>> SplitShadowParameterText(const std::string& text)
{
  std::string words = text;
  for (char& c : words)
  {
    c = c == '\t' || c == '\n' || c == '\r' ? ' ' : c;
  }
  std::istringstream stream(words);
  std::string word;
  std::vector<std::pair<std::string, std::string>> pairs;
  while (stream >> word)
  {
    std::istringstream pieces(word);
    std::string piece;
    while (std::getline(pieces, piece, ','))
    {
      const size_t equals = piece.find('=');
      if (equals != std::string::npos)
      {
        pairs.emplace_back(piece.substr(0, equals), piece.substr(equals + 1));
      }
      else if (!pairs.empty() && !piece.empty())
      {
        pairs.back().second += "," + piece;
      }
      else if (!piece.empty())
      {
        throw std::invalid_argument("shadow parameter '" + piece + "' has no value (KEY=VALUE)");
      }
    }
  }
  return pairs;
}

std::string SetShadowParameterInText(const std::string& text, const std::string& key, const std::string& value)
{
  std::vector<std::pair<std::string, std::string>> pairs = SplitShadowParameterText(text);
  bool placed = false;
  std::string result;
  for (auto& pair : pairs)
  {
    if (pair.first == key)
    {
      if (placed || value.empty())
      {
        continue; // a repeated key, or one removed
      }
      pair.second = value;
      placed = true;
    }
    result += (result.empty() ? "" : " ") + pair.first + "=" + pair.second;
  }
  if (!placed && !value.empty())
  {
    result += (result.empty() ? "" : " ") + key + "=" + value;
  }
  return result;
}

}
