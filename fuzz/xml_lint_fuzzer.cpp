// Fuzz target: the ESI XML reader and every lint rule. Any input must give diagnostics, never a
// crash, a hang or unbounded memory.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "esi/lint/lint.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    static const esi::EffectiveConfig config{};
    const esi::FileReport report = esi::lint_bytes(bytes, "fuzz.xml", config);
    (void)report;
    return 0;
}
