// A small ordered JSON object writer for the tool's machine-readable statistics.
#ifndef deepshadow_tool_Json_h
#define deepshadow_tool_Json_h

#include <string>
#include <utility>
#include <vector>

namespace deepshadow
{
namespace tool
{

class Json
{
public:
  Json& Set(const std::string& key, double value);
  Json& Set(const std::string& key, long long value);
  Json& Set(const std::string& key, int value) { return this->Set(key, static_cast<long long>(value)); }
  Json& Set(const std::string& key, bool value);
  Json& Set(const std::string& key, const std::string& value);
  Json& Set(const std::string& key, const char* value) { return this->Set(key, std::string(value)); }
  Json& Set(const std::string& key, const std::vector<double>& values);
  /** Every digit of a double (17 significant): for values a later run reads back. */
  Json& SetExact(const std::string& key, const std::vector<double>& values);
  Json& SetExact(const std::string& key, double value);
  Json& Set(const std::string& key, const std::vector<std::string>& values);
  Json& Set(const std::string& key, const Json& object);
  Json& Set(const std::string& key, const std::vector<Json>& objects);

  std::string Text(int indent = 0) const;
  /** The text of a .json file of the object (Text() and a newline). */
  std::string FileText() const { return this->Text() + "\n"; }
  /** Writes the object straight to `path`; throws UsageError if it cannot be written whole. */
  void Write(const std::string& path) const;

  static std::string Quote(const std::string& text);

private:
  Json& SetRaw(const std::string& key, std::string raw);
  std::vector<std::pair<std::string, std::string>> Members; // key, JSON text
};

/** Median of a non-empty list (mean of the two middle values for even sizes). */
double Median(std::vector<double> values);

}
}
#endif
