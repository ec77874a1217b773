#include "sim_esc/sim_fixtures.hpp"

#include <fmt/format.h>

#include <fstream>

#include "esi/net/default_slave.hpp"
#include "sim_esc/frame_builder.hpp"

namespace esi::test {

std::string ModelDevice::selector() const { return fmt::format("0x{:X}:0x{:X}", product_code, revision); }

std::vector<ModelDevice> model_devices(const std::filesystem::path& file) {
    std::vector<ModelDevice> out;
    LoadedDocument loaded = load_document_file(file);
    if (!loaded.usable()) return out;
    auto document = std::make_shared<const EsiDocument>(std::move(*loaded.document));
    for (const EtherCATInfo& info : document->infos) {
        for (const Device& device : info.devices) {
            ModelDevice m;
            m.file = file;
            m.document = document;
            m.info = &info;
            m.device = &device;
            m.vendor_id = info.vendor && info.vendor->id ? *info.vendor->id : 0;
            m.product_code = device.type.product_code.value_or(0);
            m.revision = device.type.revision_no.value_or(0);
            const sii::BuildResult built = sii::build_image(info, device);
            if (!built.ok()) continue;
            m.image = built.bytes;
            if (device.slots && !device.slots->slots.empty()) {
                // A modular device: with the modules its slots hold by default, as esi-net sets it up.
                Diagnostics ignored;
                const net::DefaultSlave slave = net::configure_default_slave(info, device, ignored);
                for (const net::ConfiguredPdo& pdo : slave.slave.pdos)
                    (pdo.direction == PdoDirection::rx ? m.output_bits : m.input_bits) += pdo.bit_size();
            } else {
                for (const Pdo& pdo : device.rx_pdos)
                    if (pdo.sm)
                        for (const PdoEntry& e : pdo.entries) m.output_bits += e.bit_len;
                for (const Pdo& pdo : device.tx_pdos)
                    if (pdo.sm)
                        for (const PdoEntry& e : pdo.entries) m.input_bits += e.bit_len;
            }
            out.push_back(std::move(m));
        }
    }
    return out;
}

std::vector<std::uint8_t> with_config_word0(std::vector<std::uint8_t> image, std::uint8_t pdi_control,
                                            std::uint8_t esc_configuration) {
    image[0] = pdi_control;
    image[1] = esc_configuration;
    image[14] = sii_crc(image);
    return image;
}

void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace esi::test
