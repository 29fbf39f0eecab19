#include "verify/executable_id.h"

#include <elf.h>
#include <link.h>

#include <cstring>

namespace arbc::verify {

namespace {

constexpr size_t align4(size_t n) { return (n + 3) & ~size_t{3}; }

// The NT_GNU_BUILD_ID note among the PT_NOTE segments of the first object dl_iterate_phdr
// reports, which is the executable itself.
int find_build_id(dl_phdr_info* info, size_t, void* data) {
  auto* id = static_cast<std::string*>(data);
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& segment = info->dlpi_phdr[i];
    if (segment.p_type != PT_NOTE) continue;
    const char* at = reinterpret_cast<const char*>(info->dlpi_addr + segment.p_vaddr);
    const char* end = at + segment.p_memsz;
    while (at + sizeof(ElfW(Nhdr)) <= end) {
      ElfW(Nhdr) note;
      std::memcpy(&note, at, sizeof note);
      const char* name = at + sizeof note;
      const char* desc = name + align4(note.n_namesz);
      if (desc + note.n_descsz > end) break;
      if (note.n_type == NT_GNU_BUILD_ID && note.n_namesz == 4 &&
          std::memcmp(name, "GNU", 4) == 0) {
        static const char kHex[] = "0123456789abcdef";
        for (size_t k = 0; k < note.n_descsz; ++k) {
          auto byte = static_cast<unsigned char>(desc[k]);
          id->push_back(kHex[byte >> 4]);
          id->push_back(kHex[byte & 15]);
        }
        return 1;
      }
      at = desc + align4(note.n_descsz);
    }
  }
  return 1;  // only the executable, the first object
}

}  // namespace

std::string executable_build_id() {
  static const std::string id = [] {
    std::string found;
    dl_iterate_phdr(find_build_id, &found);
    return found;
  }();
  return id;
}

}  // namespace arbc::verify
