#include "app/cli/failure.h"

#include "io/bad_input.h"
#include "io/interrupt.h"

#include <cstdio>
#include <new>

namespace tumble::app {

int exit_code_of(const std::exception& e) {
    if (const auto* i = dynamic_cast<const io::Interrupted*>(&e))
        return interrupted_exit_code(i->signal_number);
    return dynamic_cast<const io::BadInput*>(&e) ? kBadInput : kRunFailed;
}

int report_failure(const std::exception& e) {
    const bool interrupted = dynamic_cast<const io::Interrupted*>(&e) != nullptr;
    std::fprintf(stderr, "tumble: %s%s\n", interrupted ? "" : "error: ", e.what());
    return exit_code_of(e);
}

int run_guarded(const std::function<int()>& body) noexcept {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        std::fputs("tumble: error: out of memory\n", stderr);
        return kRunFailed;
    } catch (const std::exception& e) {
        return report_failure(e);
    } catch (...) {
        std::fputs("tumble: error: unknown failure\n", stderr);
        return kRunFailed;
    }
}

int interrupted_exit_code(int signal_number) {
    return 128 + signal_number;
}

} // namespace tumble::app
