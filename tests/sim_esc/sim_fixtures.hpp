#pragma once
// Test helper: devices from the samples and the corpus, their SII images, and what a master should
// see of them (identity, name, default process-data sizes).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "esi/load/document.hpp"
#include "esi/sii/build.hpp"

namespace esi::test {

struct ModelDevice {
    std::filesystem::path file;
    std::shared_ptr<const EsiDocument> document;
    const EtherCATInfo* info = nullptr;
    const Device* device = nullptr;
    std::uint32_t vendor_id = 0, product_code = 0, revision = 0;

    // The default PDOs (those with an SM; a modular device's with its default modules).
    std::uint32_t output_bits = 0, input_bits = 0;
    std::vector<std::uint8_t> image;                // built by the sii layer
    [[nodiscard]] std::string selector() const;     // PRODUCTCODE:REVISION for --device
};

// Every device of a file (sources and ESI files alike); empty when the file does not load.
[[nodiscard]] std::vector<ModelDevice> model_devices(const std::filesystem::path& file);

// The image with ConfigData's first word replaced and the checksum made right again.
[[nodiscard]] std::vector<std::uint8_t> with_config_word0(std::vector<std::uint8_t> image, std::uint8_t pdi_control,
                                                          std::uint8_t esc_configuration);

void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

}  // namespace esi::test
