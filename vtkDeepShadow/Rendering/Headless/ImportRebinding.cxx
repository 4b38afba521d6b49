// GOT-slot rewriting for ELF (glibc, x86_64 and aarch64). See ImportRebinding.h for why.
#include "ImportRebinding.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <dlfcn.h>
#include <elf.h>
#include <link.h>
#include <sys/mman.h>
#include <unistd.h>
#include <unordered_map>

namespace deepshadow
{
namespace headless
{
namespace
{
#if defined(__x86_64__)
constexpr unsigned JumpSlot = R_X86_64_JUMP_SLOT;
constexpr unsigned GlobalData = R_X86_64_GLOB_DAT;
#elif defined(__aarch64__)
constexpr unsigned JumpSlot = R_AARCH64_JUMP_SLOT;
constexpr unsigned GlobalData = R_AARCH64_GLOB_DAT;
#else
#error "ImportRebinding supports x86_64 and aarch64"
#endif

// The GL implementation: its calls between its own entry points must stay as they are.
bool IsGLImplementation(const char* path)
{
  const char* slash = std::strrchr(path, '/');
  const char* name = slash ? slash + 1 : path;
  static const char* const prefixes[] = { "libGL.", "libGLX", "libGLdispatch", "libOpenGL",
    "libEGL", "libGLES", "libOSMesa", "libglapi", "libgallium", "libnvidia", "libvulkan" };
  for (const char* prefix : prefixes)
  {
    if (std::strncmp(name, prefix, std::strlen(prefix)) == 0)
    {
      return true;
    }
  }
  return std::strstr(name, "_dri.so") != nullptr;
}

struct Pass
{
  std::unordered_map<std::string, void*> Wanted;
  const void* Self = nullptr;
  RebindReport* Report = nullptr;
  std::string Error;
};

// Dynamic-section pointers are relocated in place by glibc on these targets; a value below
// the load base is still file-relative.
template <typename T>
T* DynamicPointer(const dl_phdr_info* info, ElfW(Addr) value)
{
  return reinterpret_cast<T*>(value < info->dlpi_addr ? value + info->dlpi_addr : value);
}

bool WriteSlot(void** slot, void* value, const dl_phdr_info* info, std::string& error)
{
  // Slots inside PT_GNU_RELRO were made read-only after relocation: open them for the write.
  bool readOnly = false;
  for (int i = 0; i < info->dlpi_phnum; ++i)
  {
    const ElfW(Phdr)& header = info->dlpi_phdr[i];
    const auto start = info->dlpi_addr + header.p_vaddr;
    const auto address = reinterpret_cast<ElfW(Addr)>(slot);
    if (header.p_type == PT_GNU_RELRO && address >= start && address < start + header.p_memsz)
    {
      readOnly = true;
    }
  }
  const auto pageSize = static_cast<uintptr_t>(sysconf(_SC_PAGESIZE));
  void* page = reinterpret_cast<void*>(reinterpret_cast<uintptr_t>(slot) & ~(pageSize - 1));
  if (readOnly && mprotect(page, pageSize, PROT_READ | PROT_WRITE) != 0)
  {
    error = std::string("cannot rebind the GL imports of ") + info->dlpi_name + ": mprotect: " +
      std::strerror(errno);
    return false;
  }
  __atomic_store_n(slot, value, __ATOMIC_RELEASE);
  if (readOnly)
  {
    mprotect(page, pageSize, PROT_READ);
  }
  return true;
}

int VisitObject(dl_phdr_info* info, size_t, void* data)
{
  auto& pass = *static_cast<Pass*>(data);
  const char* name = info->dlpi_name ? info->dlpi_name : "";
  const auto* dynamic = static_cast<const ElfW(Dyn)*>(nullptr);
  // Whether an address lies in this object (a lazily bound slot still points at its own PLT).
  auto inside = [info](const void* address) {
    const auto value = reinterpret_cast<ElfW(Addr)>(address);
    for (int i = 0; i < info->dlpi_phnum; ++i)
    {
      const ElfW(Phdr)& header = info->dlpi_phdr[i];
      const auto start = info->dlpi_addr + header.p_vaddr;
      if (header.p_type == PT_LOAD && value >= start && value < start + header.p_memsz)
      {
        return true;
      }
    }
    return false;
  };
  for (int i = 0; i < info->dlpi_phnum; ++i)
  {
    if (info->dlpi_phdr[i].p_type == PT_DYNAMIC)
    {
      dynamic = reinterpret_cast<const ElfW(Dyn)*>(info->dlpi_addr + info->dlpi_phdr[i].p_vaddr);
    }
  }
  if (!dynamic || inside(pass.Self) || IsGLImplementation(name) || std::strstr(name, "linux-vdso"))
  {
    return 0;
  }

  const ElfW(Sym)* symbols = nullptr;
  const char* strings = nullptr;
  const ElfW(Rela)* tables[2] = { nullptr, nullptr };
  size_t sizes[2] = { 0, 0 };
  for (const ElfW(Dyn)* entry = dynamic; entry->d_tag != DT_NULL; ++entry)
  {
    switch (entry->d_tag)
    {
      case DT_SYMTAB:
        symbols = DynamicPointer<const ElfW(Sym)>(info, entry->d_un.d_ptr);
        break;
      case DT_STRTAB:
        strings = DynamicPointer<const char>(info, entry->d_un.d_ptr);
        break;
      case DT_JMPREL:
        tables[0] = DynamicPointer<const ElfW(Rela)>(info, entry->d_un.d_ptr);
        break;
      case DT_PLTRELSZ:
        sizes[0] = entry->d_un.d_val;
        break;
      case DT_RELA:
        tables[1] = DynamicPointer<const ElfW(Rela)>(info, entry->d_un.d_ptr);
        break;
      case DT_RELASZ:
        sizes[1] = entry->d_un.d_val;
        break;
      default:
        break;
    }
  }
  if (!symbols || !strings)
  {
    return 0;
  }

  bool counted = false;
  for (int t = 0; t < 2; ++t)
  {
    for (size_t i = 0; tables[t] && i < sizes[t] / sizeof(ElfW(Rela)); ++i)
    {
      const ElfW(Rela)& relocation = tables[t][i];
      const auto type = ELF64_R_TYPE(relocation.r_info);
      const auto index = ELF64_R_SYM(relocation.r_info);
      if ((type != JumpSlot && type != GlobalData) || index == 0)
      {
        continue;
      }
      const ElfW(Sym)& symbol = symbols[index];
      if (symbol.st_shndx != SHN_UNDEF) // the object defines it: an internal call
      {
        continue;
      }
      const auto wanted = pass.Wanted.find(strings + symbol.st_name);
      if (wanted == pass.Wanted.end())
      {
        continue;
      }
      auto** slot = reinterpret_cast<void**>(info->dlpi_addr + relocation.r_offset);
      if (!counted)
      {
        ++pass.Report->Objects;
        counted = true;
      }
      if (*slot == wanted->second)
      {
        ++pass.Report->AlreadyBound;
        continue;
      }
      // Not yet bound (lazy binding: the slot holds this object's PLT stub): the linker would
      // bind it to the first definition in order, ours or not; set it now, but it was not
      // bound elsewhere.
      const bool unbound = inside(*slot);
      if (!WriteSlot(slot, wanted->second, info, pass.Error))
      {
        return 1;
      }
      ++(unbound ? pass.Report->Unbound : pass.Report->Rewritten);
    }
  }
  return 0;
}

int CountObjects(dl_phdr_info* info, size_t, void* data)
{
  *static_cast<unsigned long long*>(data) = info->dlpi_adds;
  return 1; // dlpi_adds is the same in every entry: the first one is enough
}
}

bool RebindImports(const std::vector<ImportDefinition>& definitions, const void* self,
  RebindReport& report, std::string& error)
{
  Pass pass;
  pass.Self = self;
  pass.Report = &report;
  for (const ImportDefinition& definition : definitions)
  {
    pass.Wanted.emplace(definition.Name, definition.Address);
  }
  if (dl_iterate_phdr(VisitObject, &pass) != 0)
  {
    error = pass.Error;
    return false;
  }
  return true;
}

unsigned long long LoadedObjectGeneration()
{
  unsigned long long adds = 0;
  dl_iterate_phdr(CountObjects, &adds);
  return adds;
}

}
}
