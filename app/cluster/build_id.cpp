#include "app/cluster/build_id.h"

#include "app/scene/content_hash.h"

#include <elf.h>
#include <link.h>

#include <cstring>
#include <fstream>
#include <iterator>

namespace tumble::app {

namespace {

// The NT_GNU_BUILD_ID note of the main program (the first object dl_iterate_phdr reports).
int find_note(dl_phdr_info* info, std::size_t, void* out) {
    auto& id = *static_cast<std::string*>(out);
    for (int i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& segment = info->dlpi_phdr[i];
        if (segment.p_type != PT_NOTE) continue;
        const char* at = reinterpret_cast<const char*>(info->dlpi_addr + segment.p_vaddr);
        const char* end = at + segment.p_memsz;
        while (at + sizeof(ElfW(Nhdr)) <= end) {
            const auto* note = reinterpret_cast<const ElfW(Nhdr)*>(at);
            const char* name = at + sizeof(ElfW(Nhdr));
            const char* desc = name + ((note->n_namesz + 3) & ~3u);
            if (note->n_type == NT_GNU_BUILD_ID && note->n_namesz == 4 &&
                std::memcmp(name, "GNU", 4) == 0 && desc + note->n_descsz <= end) {
                static const char digits[] = "0123456789abcdef";
                for (unsigned k = 0; k < note->n_descsz; ++k) {
                    const auto byte = static_cast<unsigned char>(desc[k]);
                    id += digits[byte >> 4];
                    id += digits[byte & 15];
                }
                return 1;
            }
            at = desc + ((note->n_descsz + 3) & ~3u);
        }
    }
    return 1; // only the main program is of interest
}

std::string compute() {
    std::string id;
    dl_iterate_phdr(find_note, &id);
    if (!id.empty()) return id;
    std::ifstream self("/proc/self/exe", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(self)), {});
    ContentHash hash;
    hash.add(bytes);
    return "file-" + hash.hex();
}

} // namespace

const std::string& build_id() {
    static const std::string id = compute();
    return id;
}

} // namespace tumble::app
