#include "Outputs.h"

#include "Options.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

namespace deepshadow
{
namespace tool
{
namespace
{
// The directory part of a path as given ("." for a bare name, "/" for the root).
std::string DirectoryOf(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

// The path with its directory resolved (links, "..", "."), for comparing names of files that
// may not exist yet; the path as given if the directory cannot be resolved.
std::string Canonical(const std::string& path)
{
  char resolved[PATH_MAX];
  const size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (!realpath(DirectoryOf(path).c_str(), resolved))
  {
    return path;
  }
  const std::string directory = resolved;
  return (directory == "/" ? "" : directory) + "/" + name;
}

bool SameExistingFile(const std::string& a, const std::string& b)
{
  struct stat sa, sb;
  return stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
    sa.st_ino == sb.st_ino;
}

std::string Named(const NamedFile& file)
{
  return file.Option + " " + file.Path;
}

mode_t CreationMode()
{
  const mode_t mask = umask(0);
  umask(mask);
  return 0666 & ~mask;
}

// Writes all of `bytes` to `fd`; false with errno set on a short or failed write.
bool WriteAll(int fd, const std::string& bytes)
{
  size_t done = 0;
  while (done < bytes.size())
  {
    const ssize_t wrote = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (wrote < 0 && errno == EINTR)
    {
      continue;
    }
    if (wrote <= 0)
    {
      if (wrote == 0)
      {
        errno = EIO;
      }
      return false;
    }
    done += static_cast<size_t>(wrote);
  }
  return true;
}
}

Outputs::~Outputs()
{
  for (const auto& file : this->Staged)
  {
    std::remove(file.first.c_str());
  }
}

bool Outputs::IsStandardOutput(const std::string& path)
{
  return path == "-" || path == "/dev/stdout";
}

void Outputs::RequireWritable(const std::string& path)
{
  if (path.empty())
  {
    throw UsageError("an output file name is empty");
  }
  if (IsStandardOutput(path))
  {
    return;
  }
  const std::string directory = DirectoryOf(path);
  struct stat info;
  if (stat(directory.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
  {
    throw UsageError("cannot write " + path + ": no such directory " + directory);
  }
  if (access(directory.c_str(), W_OK) != 0)
  {
    throw UsageError("cannot write " + path + ": the directory " + directory + " is not writable");
  }
  const size_t slash = path.find_last_of('/');
  const size_t nameLength = path.size() - (slash == std::string::npos ? 0 : slash + 1);
  const long longest = pathconf(directory.c_str(), _PC_NAME_MAX);
  if (longest > 0 && nameLength > static_cast<size_t>(longest))
  {
    throw UsageError("cannot write " + path + ": its name is longer than the " +
      std::to_string(longest) + " characters this file system allows");
  }
  if (stat(path.c_str(), &info) == 0)
  {
    if (S_ISDIR(info.st_mode))
    {
      throw UsageError("cannot write " + path + ": it is a directory");
    }
    if (!S_ISREG(info.st_mode))
    {
      throw UsageError("cannot write " + path + ": it exists and is not a regular file (a "
        "device, a pipe or a socket would be replaced by a file); give a file name, or - for "
        "standard output");
    }
  }
}

void Outputs::RequireDistinct(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs)
{
  for (size_t i = 0; i < outputs.size(); ++i)
  {
    const NamedFile& output = outputs[i];
    const bool standard = IsStandardOutput(output.Path);
    for (size_t j = 0; j < i; ++j)
    {
      const NamedFile& other = outputs[j];
      const bool same = standard || IsStandardOutput(other.Path)
        ? standard == IsStandardOutput(other.Path)
        : Canonical(output.Path) == Canonical(other.Path) || SameExistingFile(output.Path, other.Path);
      if (same)
      {
        throw UsageError(Named(other) + " and " + Named(output) +
          " are the same file; give each output its own name");
      }
    }
    if (standard)
    {
      continue;
    }
    for (const NamedFile& input : inputs)
    {
      if (SameExistingFile(output.Path, input.Path))
      {
        throw UsageError(Named(output) + " is the input " + Named(input) +
          ": it would be replaced; give the output another name");
      }
    }
  }
}

void Outputs::Write(const std::string& path, const std::string& bytes)
{
  if (IsStandardOutput(path))
  {
    this->ToStandardOutput.push_back(bytes);
    return;
  }
  RequireWritable(path);
  // A short name beside the destination (a rename never crosses file systems), whatever
  // the length of the destination's own name.
  const size_t slash = path.find_last_of('/');
  std::string temporary =
    (slash == std::string::npos ? std::string() : path.substr(0, slash + 1)) + ".deepshadow-XXXXXX";
  const int fd = mkstemp(&temporary[0]);
  if (fd < 0)
  {
    throw UsageError("cannot write " + path + ": " + std::strerror(errno));
  }
  this->Staged.emplace_back(temporary, path);
  fchmod(fd, CreationMode()); // mkstemp makes 0600; the file a plain create would make
  const bool written = WriteAll(fd, bytes);
  const int error = errno;
  if (close(fd) != 0 || !written)
  {
    throw UsageError("cannot write " + path + ": " + std::strerror(written ? errno : error));
  }
}

void Outputs::Commit()
{
  for (const auto& file : this->Staged)
  {
    if (std::rename(file.first.c_str(), file.second.c_str()) != 0)
    {
      throw UsageError("cannot write " + file.second + ": " + std::strerror(errno));
    }
  }
  this->Staged.clear();
  for (const std::string& bytes : this->ToStandardOutput)
  {
    std::fflush(stdout);
    if (!WriteAll(STDOUT_FILENO, bytes))
    {
      throw UsageError(std::string("cannot write standard output: ") + std::strerror(errno));
    }
  }
  this->ToStandardOutput.clear();
}

}
}
