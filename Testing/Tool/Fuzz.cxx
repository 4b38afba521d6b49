// DeepShadowFuzz: mutates well-formed input files (SeedFiles.h: .vti, .mhd/.mha, .nrrd/.nhdr,
// .ply, .stl, .obj, .vtk, .vtp) and CSG expressions with a fixed seed, and runs on each
//   1. the reader alone (vtkDeepShadowVolumeReader or vtkDeepShadowMeshReader, in a forked
//      child), which must finish, with data or with its one-line error;
//   2. the deepshadow tool, which must exit 0, or 2 with one line "deepshadow: ..." on stderr
//      and no output file left behind;
// each under a time limit (wall clock and CPU) and an address-space limit (ulimit -v). A
// signal, a hang, another exit code or a second line fails the case; the mutated file is
// kept in WORK/failures with the command that failed on it. Case i of seed S is the same file
// on every machine (std::mt19937_64 seeded with S and i, no other randomness).
//
// Usage: DeepShadowFuzz --tool PATH --work DIR [--seed S] [--count N] [--first I]
//                       [--time-limit SECONDS] [--memory-limit MIB (0: none, for ASan)]
#include "SeedFiles.h"

#include "vtkDeepShadowMeshReader.h"
#include "vtkDeepShadowVolumeReader.h"

#include "vtkNew.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace
{
using deepshadow::testing::SeedFile;
using Bytes = std::string;

struct Settings
{
  std::string Tool;
  std::string Work;
  unsigned long long Seed = 1;
  int Count = 200;
  int First = 0;
  double TimeLimit = 20.0;
  long long MemoryLimitMiB = 2048;
};

Bytes ReadFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void WriteFile(const std::string& path, const Bytes& bytes)
{
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// ---- Mutations ------------------------------------------------------------------------------

// Numbers that break readers: signs, zero, limits of 32 and 64 bits, huge and tiny floats.
const std::vector<std::string> Interesting = { "0", "-1", "1", "2", "255", "256", "65535",
  "2147483647", "2147483648", "4294967295", "4294967296", "-2147483648", "100000",
  "1000000000", "9223372036854775807", "18446744073709551616", "1e308", "-1e308", "1e-308",
  "1e30", "1e-30", "nan", "inf", "-inf", "0.5", "banana", "" };

// The header part of a file: text before the first byte that is not printable ASCII.
size_t TextPrefix(const Bytes& bytes)
{
  size_t n = 0;
  while (n < bytes.size() && n < 65536 &&
    (static_cast<unsigned char>(bytes[n]) >= 32 || bytes[n] == '\n' || bytes[n] == '\r' || bytes[n] == '\t') &&
    static_cast<unsigned char>(bytes[n]) < 127)
  {
    ++n;
  }
  return n;
}

// One mutation of `bytes`, chosen by `random`; returns what it did (for the failure report).
std::string Mutate(Bytes& bytes, std::mt19937_64& random)
{
  auto pick = [&](size_t n) { return n == 0 ? size_t(0) : static_cast<size_t>(random() % n); };
  const size_t text = TextPrefix(bytes);
  const int kind = static_cast<int>(random() % 8);
  std::ostringstream what;
  if ((kind <= 2) && text > 0)
  {
    // A number (or word) in the header replaced by an interesting one.
    std::vector<std::pair<size_t, size_t>> tokens;
    for (size_t i = 0; i < text;)
    {
      while (i < text && std::strchr(" \t\r\n=:,\"<>/()", bytes[i]))
      {
        ++i;
      }
      const size_t start = i;
      while (i < text && !std::strchr(" \t\r\n=:,\"<>/()", bytes[i]))
      {
        ++i;
      }
      if (i > start)
      {
        tokens.emplace_back(start, i - start);
      }
    }
    if (!tokens.empty())
    {
      // Prefer numbers: they are what sizes, counts, offsets and spacings are made of.
      auto token = tokens[pick(tokens.size())];
      for (int tries = 0; tries < 8 && !std::isdigit(static_cast<unsigned char>(bytes[token.first])) &&
           bytes[token.first] != '-';
           ++tries)
      {
        token = tokens[pick(tokens.size())];
      }
      const std::string value = Interesting[pick(Interesting.size())];
      what << "token '" << bytes.substr(token.first, token.second) << "' at " << token.first
           << " -> '" << value << "'";
      bytes.replace(token.first, token.second, value);
      return what.str();
    }
  }
  if (kind == 3 && text > 0)
  {
    // A header line deleted or duplicated.
    std::vector<size_t> starts = { 0 };
    for (size_t i = 0; i + 1 < text; ++i)
    {
      if (bytes[i] == '\n')
      {
        starts.push_back(i + 1);
      }
    }
    const size_t line = pick(starts.size());
    const size_t begin = starts[line];
    const size_t end = line + 1 < starts.size() ? starts[line + 1] : text;
    const bool remove = random() % 2 == 0;
    what << (remove ? "deleted" : "duplicated") << " header line " << line;
    if (remove)
    {
      bytes.erase(begin, end - begin);
    }
    else
    {
      bytes.insert(end, bytes.substr(begin, end - begin));
    }
    return what.str();
  }
  if (kind == 4 && !bytes.empty())
  {
    const size_t at = pick(bytes.size());
    what << "truncated at " << at << " of " << bytes.size();
    bytes.resize(at);
    return what.str();
  }
  if (kind == 5 && !bytes.empty())
  {
    // Interesting bytes over the data: zeros, all ones, sign bits, NaN/Inf patterns.
    static const unsigned char patterns[][4] = { { 0, 0, 0, 0 }, { 0xff, 0xff, 0xff, 0xff },
      { 0xff, 0xff, 0xff, 0x7f }, { 0, 0, 0, 0x80 }, { 0, 0, 0xc0, 0x7f }, { 0, 0, 0x80, 0x7f } };
    const size_t at = pick(bytes.size());
    const auto& p = patterns[pick(6)];
    what << "4 bytes at " << at << " set to " << int(p[0]) << "," << int(p[1]) << "," << int(p[2])
         << "," << int(p[3]);
    for (size_t i = 0; i < 4 && at + i < bytes.size(); ++i)
    {
      bytes[at + i] = static_cast<char>(p[i]);
    }
    return what.str();
  }
  if (kind == 6 && !bytes.empty())
  {
    const size_t at = pick(bytes.size()), length = 1 + pick(std::min<size_t>(bytes.size() - at, 64));
    const size_t to = pick(bytes.size());
    what << "copied " << length << " bytes from " << at << " to " << to;
    bytes.insert(to, bytes.substr(at, length));
    return what.str();
  }
  // Random bit flips.
  const int flips = 1 + static_cast<int>(random() % 8);
  what << flips << " bit flips";
  for (int f = 0; f < flips && !bytes.empty(); ++f)
  {
    bytes[pick(bytes.size())] ^= static_cast<char>(1 << (random() % 8));
  }
  return what.str();
}

std::string MutateExpression(std::string text, std::mt19937_64& random)
{
  const std::string alphabet = "ABCZab(),unioterdfsc ";
  const int edits = 1 + static_cast<int>(random() % 4);
  for (int e = 0; e < edits; ++e)
  {
    const size_t at = text.empty() ? 0 : static_cast<size_t>(random() % (text.size() + 1));
    switch (random() % 5)
    {
      case 0:
        text.insert(at, 1, alphabet[random() % alphabet.size()]);
        break;
      case 1:
        if (at < text.size())
        {
          text.erase(at, 1);
        }
        break;
      case 2:
        if (at < text.size())
        {
          text[at] = alphabet[random() % alphabet.size()];
        }
        break;
      case 3:
      {
        // Deep nesting: parsers that recurse must refuse it, not overflow the stack.
        const int depth = static_cast<int>(random() % 4000);
        std::string nested;
        for (int d = 0; d < depth; ++d)
        {
          nested += "union(A,";
        }
        text = nested + text + std::string(static_cast<size_t>(depth), ')');
        break;
      }
      default:
        text = text.substr(0, at);
        break;
    }
  }
  return text;
}

// ---- Running ------------------------------------------------------------------------------------

struct Result
{
  bool Signaled = false;
  bool TimedOut = false;
  int Code = 0;
  int Signal = 0;
  std::string Stderr;
};

void Limit(const Settings& settings)
{
  struct rlimit cpu = { static_cast<rlim_t>(settings.TimeLimit) + 1, static_cast<rlim_t>(settings.TimeLimit) + 2 };
  setrlimit(RLIMIT_CPU, &cpu);
  struct rlimit core = { 0, 0 };
  setrlimit(RLIMIT_CORE, &core);
  if (settings.MemoryLimitMiB > 0)
  {
    const rlim_t bytes = static_cast<rlim_t>(settings.MemoryLimitMiB) << 20;
    struct rlimit memory = { bytes, bytes };
    setrlimit(RLIMIT_AS, &memory);
  }
}

// Runs `child` in a forked process under the limits, its stderr into `errFile`.
template <typename Child>
Result RunLimited(const Settings& settings, const std::string& errFile, Child child)
{
  Result result;
  const pid_t pid = fork();
  if (pid == 0)
  {
    Limit(settings);
    const int err = open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(err, 2);
    child();
    _exit(127);
  }
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0)
  {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > settings.TimeLimit)
    {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      result.TimedOut = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  result.Signaled = !result.TimedOut && WIFSIGNALED(status);
  result.Signal = result.Signaled ? WTERMSIG(status) : 0;
  result.Code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.Stderr = ReadFile(errFile);
  return result;
}

Result RunTool(const Settings& settings, const std::vector<std::string>& args)
{
  return RunLimited(settings, settings.Work + "/stderr.txt", [&]() {
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(settings.Tool.c_str()));
    for (const auto& a : args)
    {
      argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    execv(settings.Tool.c_str(), argv.data());
  });
}

Result RunReader(const Settings& settings, SeedFile::Kinds kind, const std::string& file)
{
  return RunLimited(settings, settings.Work + "/reader-stderr.txt", [&]() {
    if (kind == SeedFile::Volume)
    {
      vtkNew<vtkDeepShadowVolumeReader> reader;
      reader->SetFileName(file.c_str());
      reader->Update();
    }
    else
    {
      vtkNew<vtkDeepShadowMeshReader> reader;
      reader->SetFileName(file.c_str());
      reader->Update();
    }
    std::fflush(nullptr);
    _exit(0);
  });
}

std::string Describe(const Result& r)
{
  if (r.TimedOut)
  {
    return "no answer within the time limit (a hang?)";
  }
  if (r.Signaled)
  {
    return std::string("killed by signal ") + std::to_string(r.Signal) + " (" + strsignal(r.Signal) + ")";
  }
  return "exit " + std::to_string(r.Code);
}

bool FileExists(const std::string& path)
{
  struct stat info;
  return stat(path.c_str(), &info) == 0;
}

std::string Extension(const std::string& name)
{
  const size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? "" : name.substr(dot);
}

int Usage()
{
  std::fprintf(stderr, "usage: DeepShadowFuzz --tool PATH --work DIR [--seed S] [--count N] "
                       "[--first I] [--time-limit SECONDS] [--memory-limit MIB]\n");
  return 2;
}
}

int main(int argc, char* argv[])
{
  Settings settings;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--tool")
      settings.Tool = value;
    else if (key == "--work")
      settings.Work = value;
    else if (key == "--seed")
      settings.Seed = std::strtoull(value.c_str(), nullptr, 10);
    else if (key == "--count")
      settings.Count = std::atoi(value.c_str());
    else if (key == "--first")
      settings.First = std::atoi(value.c_str());
    else if (key == "--time-limit")
      settings.TimeLimit = std::atof(value.c_str());
    else if (key == "--memory-limit")
      settings.MemoryLimitMiB = std::atoll(value.c_str());
    else
      return Usage();
  }
  if (settings.Tool.empty() || settings.Work.empty() || argc % 2 == 0)
  {
    return Usage();
  }
  const std::string seeds = settings.Work + "/seeds", failures = settings.Work + "/failures";
  mkdir(settings.Work.c_str(), 0755);
  mkdir(seeds.c_str(), 0755);
  mkdir(failures.c_str(), 0755);
  const std::vector<SeedFile> files = deepshadow::testing::WriteSeedFiles(seeds);
  const std::vector<std::string> expressions = deepshadow::testing::SeedExpressions();
  const std::string out = settings.Work + "/out.png";

  int failed = 0, exit0 = 0, exit2 = 0;
  std::map<std::string, int> reasons; // the first words of the error lines, for the summary
  const auto start = std::chrono::steady_clock::now();
  for (int i = settings.First; i < settings.First + settings.Count; ++i)
  {
    std::mt19937_64 random(settings.Seed * 1000003ULL + static_cast<unsigned long long>(i));
    const size_t target = static_cast<size_t>(i) % (files.size() + 1);
    std::vector<std::string> args;
    std::string mutation, caseFile;
    bool readerOk = true;
    Result reader;
    if (target == files.size())
    {
      // A CSG expression over two bounds.
      const std::string expression = MutateExpression(expressions[random() % expressions.size()], random);
      mutation = "expression '" + (expression.size() > 80 ? expression.substr(0, 77) + "..." : expression) + "'";
      args = { "render", "--scene", "box", "--scale", "0.1", "--size", "24x24", "--frames", "1",
        "--bound", seeds + "/bound.obj", "--bound", seeds + "/mesh.obj", "--csg", expression,
        "--out", out };
    }
    else
    {
      const SeedFile& seed = files[target];
      // The main file mostly; a data file it names sometimes.
      const bool companion = !seed.Companions.empty() && random() % 5 == 0;
      for (const std::string& c : seed.Companions)
      {
        WriteFile(settings.Work + "/" + c, ReadFile(seeds + "/" + c));
      }
      const std::string mutated = companion ? seed.Companions.front() : seed.Name;
      Bytes bytes = ReadFile(seeds + "/" + mutated);
      const int rounds = 1 + static_cast<int>(random() % 3);
      for (int r = 0; r < rounds; ++r)
      {
        mutation += (r ? "; " : "") + Mutate(bytes, random);
      }
      mutation = mutated + ": " + mutation;
      caseFile = settings.Work + "/case" + Extension(seed.Name);
      if (companion)
      {
        WriteFile(caseFile, ReadFile(seeds + "/" + seed.Name));
        WriteFile(settings.Work + "/" + mutated, bytes);
      }
      else
      {
        WriteFile(caseFile, bytes);
      }
      reader = RunReader(settings, seed.Kind, caseFile);
      readerOk = !reader.TimedOut && !reader.Signaled && reader.Code == 0;
      if (seed.Kind == SeedFile::Volume)
      {
        args = { "render", "--volume", caseFile, "--size", "24x24", "--frames", "1", "--out", out };
        if (random() % 3 == 0)
        {
          args.insert(args.end(), { "--technique", "dsm", "--shadow-map-size", "32" });
        }
      }
      else
      {
        args = { "render", "--scene", "box", "--scale", "0.1", "--size", "24x24", "--frames", "1",
          random() % 2 ? "--mesh" : "--bound", caseFile, "--out", out };
      }
    }
    std::remove(out.c_str());
    const Result tool = RunTool(settings, args);
    std::string verdict;
    if (!readerOk)
    {
      verdict = "the reader alone: " + Describe(reader);
    }
    else if (tool.TimedOut || tool.Signaled || (tool.Code != 0 && tool.Code != 2))
    {
      verdict = "the tool: " + Describe(tool);
    }
    else if (tool.Code == 2)
    {
      const bool oneLine = tool.Stderr.rfind("deepshadow: ", 0) == 0 &&
        tool.Stderr.find('\n') == tool.Stderr.size() - 1;
      if (!oneLine)
      {
        verdict = "the tool: exit 2 without exactly one line 'deepshadow: ...' on stderr";
      }
      else if (FileExists(out))
      {
        verdict = "the tool: exit 2 but the output file was left behind";
      }
      else
      {
        ++exit2;
        // The problem without the file name: after "cannot read ... 'NAME': " or
        // "cannot render NAME: ".
        std::string reason = tool.Stderr.substr(12, tool.Stderr.size() - 13);
        const size_t named = reason.find("': ");
        if (named != std::string::npos)
        {
          reason = reason.substr(named + 3);
        }
        else if (reason.rfind("cannot render", 0) == 0 && reason.find(": ") != std::string::npos)
        {
          reason = reason.substr(reason.find(": ") + 2);
        }
        reasons[reason.substr(0, 48)]++;
      }
    }
    else
    {
      ++exit0;
    }
    if (!verdict.empty())
    {
      ++failed;
      const std::string kept = failures + "/case" + std::to_string(i) + (caseFile.empty() ? ".txt" : Extension(caseFile));
      if (!caseFile.empty())
      {
        WriteFile(kept, ReadFile(caseFile));
      }
      else
      {
        WriteFile(kept, args[args.size() - 3]);
      }
      std::printf("FAILED case %d (%s): %s\n  kept as %s\n  stderr: %s\n", i, mutation.c_str(),
        verdict.c_str(), kept.c_str(), (readerOk ? tool.Stderr : reader.Stderr).substr(0, 600).c_str());
      std::fflush(stdout);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%d cases (seed %llu, from %d) in %.1f s: %d rendered (exit 0), %d refused with one "
              "line (exit 2), %d failed\n",
    settings.Count, settings.Seed, settings.First, seconds, exit0, exit2, failed);
  // The ten commonest refusals.
  std::vector<std::pair<int, std::string>> common;
  for (const auto& reason : reasons)
  {
    common.emplace_back(reason.second, reason.first);
  }
  std::sort(common.rbegin(), common.rend());
  for (size_t r = 0; r < common.size() && r < 10; ++r)
  {
    std::printf("  %4d x %s...\n", common[r].first, common[r].second.c_str());
  }
  return failed == 0 ? 0 : 1;
}
