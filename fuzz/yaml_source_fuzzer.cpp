// Fuzz target: the YAML device source front end, derivation, every lint rule on the derived
// model, and the ESI writer on it (esi-gen writes the derived model as ESI XML). Any input must
// give diagnostics, never a crash, a hang or unbounded memory.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "esi/lint/lint.hpp"
#include "esi/xml/writer.hpp"
#include "esi/yaml/source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const esi::DeviceSource source = esi::load_device_source(bytes, "fuzz.yaml");
    if (source.document) {
        static const esi::EffectiveConfig config{};
        const esi::Diagnostics found = esi::run_rules(*source.document, config);
        (void)found;
        (void)esi::write_esi(*source.document);
    }
    return 0;
}
