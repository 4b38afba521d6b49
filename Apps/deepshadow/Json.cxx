#include "Json.h"

#include "Options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace deepshadow
{
namespace tool
{
namespace
{
// Six significant digits for statistics; 17 (a double exactly) where values are read back.
std::string Number(double value, int digits = 6)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
  return buffer;
}

std::string NumberArray(const std::vector<double>& values, int digits)
{
  std::string raw = "[";
  for (size_t i = 0; i < values.size(); ++i)
  {
    raw += (i ? ", " : "") + Number(values[i], digits);
  }
  return raw + "]";
}
}

std::string Json::Quote(const std::string& text)
{
  std::string quoted = "\"";
  for (char c : text)
  {
    switch (c)
    {
      case '"':
        quoted += "\\\"";
        break;
      case '\\':
        quoted += "\\\\";
        break;
      case '\n':
        quoted += "\\n";
        break;
      case '\t':
        quoted += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20)
        {
          char buffer[8];
          std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
          quoted += buffer;
        }
        else
        {
          quoted += c;
        }
    }
  }
  return quoted + "\"";
}

Json& Json::SetRaw(const std::string& key, std::string raw)
{
  for (auto& member : this->Members)
  {
    if (member.first == key)
    {
      member.second = std::move(raw);
      return *this;
    }
  }
  this->Members.emplace_back(key, std::move(raw));
  return *this;
}

Json& Json::Set(const std::string& key, double value)
{
  return this->SetRaw(key, Number(value));
}

Json& Json::Set(const std::string& key, long long value)
{
  return this->SetRaw(key, std::to_string(value));
}

Json& Json::Set(const std::string& key, bool value)
{
  return this->SetRaw(key, value ? "true" : "false");
}

Json& Json::Set(const std::string& key, const std::string& value)
{
  return this->SetRaw(key, Quote(value));
}

Json& Json::Set(const std::string& key, const std::vector<double>& values)
{
  return this->SetRaw(key, NumberArray(values, 6));
}

Json& Json::SetExact(const std::string& key, double value)
{
  return this->SetRaw(key, Number(value, 17));
}

Json& Json::SetExact(const std::string& key, const std::vector<double>& values)
{
  return this->SetRaw(key, NumberArray(values, 17));
}

Json& Json::Set(const std::string& key, const std::vector<std::string>& values)
{
  std::string raw = "[";
  for (size_t i = 0; i < values.size(); ++i)
  {
    raw += (i ? ", " : "") + Quote(values[i]);
  }
  return this->SetRaw(key, raw + "]");
}

Json& Json::Set(const std::string& key, const Json& object)
{
  return this->SetRaw(key, object.Text(2));
}

Json& Json::Set(const std::string& key, const std::vector<Json>& objects)
{
  std::string raw = "[";
  for (size_t i = 0; i < objects.size(); ++i)
  {
    raw += (i ? ",\n    " : "\n    ") + objects[i].Text(4);
  }
  return this->SetRaw(key, raw + (objects.empty() ? "]" : "\n  ]"));
}

std::string Json::Text(int indent) const
{
  const std::string pad(static_cast<size_t>(indent) + 2, ' ');
  std::ostringstream out;
  out << "{";
  for (size_t i = 0; i < this->Members.size(); ++i)
  {
    out << (i ? ",\n" : "\n") << pad << Quote(this->Members[i].first) << ": "
        << this->Members[i].second;
  }
  out << "\n" << std::string(static_cast<size_t>(indent), ' ') << "}";
  return out.str();
}

void Json::Write(const std::string& path) const
{
  std::ofstream file(path);
  file << this->FileText();
  file.close();
  if (!file)
  {
    throw UsageError("cannot write " + path);
  }
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}
}
