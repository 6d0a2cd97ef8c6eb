#include "app/run/peak_memory.h"

#include <cstdio>
#include <sys/resource.h>

namespace tumble::app {

std::int64_t peak_memory_bytes() {
    struct rusage usage {};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
    return static_cast<std::int64_t>(usage.ru_maxrss) * 1024; // Linux reports kibibytes
}

std::string describe_peak_memory() {
    char text[48];
    std::snprintf(text, sizeof text, "peak memory %.1f MiB",
                  static_cast<double>(peak_memory_bytes()) / (1 << 20));
    return text;
}

} // namespace tumble::app
