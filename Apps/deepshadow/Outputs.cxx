#include "Outputs.h"

#include "Options.h"

#include <cstdio>
#include <sys/stat.h>
#include <unistd.h>

namespace deepshadow
{
namespace tool
{

Outputs::~Outputs()
{
  for (const auto& file : this->Staged)
  {
    std::remove(file.first.c_str());
  }
}

void Outputs::RequireWritable(const std::string& path)
{
  if (path.empty())
  {
    throw UsageError("an output file name is empty");
  }
  const size_t slash = path.find_last_of('/');
  const std::string directory =
    slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  struct stat info;
  if (stat(directory.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
  {
    throw UsageError("cannot write " + path + ": no such directory " + directory);
  }
  if (access(directory.c_str(), W_OK) != 0)
  {
    throw UsageError("cannot write " + path + ": the directory " + directory + " is not writable");
  }
  if (stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
  {
    throw UsageError("cannot write " + path + ": it is a directory");
  }
}

std::string Outputs::Stage(const std::string& path)
{
  RequireWritable(path);
  const size_t slash = path.find_last_of('/');
  const std::string directory = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  // A dot file in the same directory, so that the rename cannot cross file systems.
  const std::string temporary =
    directory + "." + name + "." + std::to_string(getpid()) + ".partial";
  this->Staged.emplace_back(temporary, path);
  return temporary;
}

void Outputs::Commit()
{
  for (const auto& file : this->Staged)
  {
    if (std::rename(file.first.c_str(), file.second.c_str()) != 0)
    {
      throw UsageError("cannot write " + file.second);
    }
  }
  this->Staged.clear();
}

}
}
