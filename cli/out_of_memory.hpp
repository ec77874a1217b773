#pragma once
// An input too large for the machine's memory ends a tool with a message and exit code 2 (an
// input that cannot be read), not with std::bad_alloc's abort and core dump. The library reports
// it where it can (the XML reader returns a located io-error); an std::bad_alloc that no code
// catches, in any thread, ends here. Other uncaught exceptions still abort.

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>

#include "esi/io/leftovers.hpp"

namespace esi::cli {

inline const char* out_of_memory_tool = "esi";

[[noreturn]] inline void on_terminate() {
    bool out_of_memory = false;
    if (const std::exception_ptr in_flight = std::current_exception()) {
        try {
            std::rethrow_exception(in_flight);
        } catch (const std::bad_alloc&) {
            out_of_memory = true;
        } catch (...) {
        }
    }
    esi::remove_registered_leftovers();
    if (!out_of_memory) std::abort();
    // Nothing may allocate here.
    const char* tool = out_of_memory_tool;
    const char message[] = ": out of memory (an input is too large for this machine's memory)\n";
    (void)!::write(STDERR_FILENO, tool, std::strlen(tool));
    (void)!::write(STDERR_FILENO, message, sizeof message - 1);
    ::_exit(2);
}

inline void exit_with_code_two_when_out_of_memory(const char* tool) {
    out_of_memory_tool = tool;
    std::set_terminate(on_terminate);
}

}  // namespace esi::cli
