// Rules of the eeprom area: the Eeprom element from which tools build the SII EEPROM image
// (ETG.2010). It is either a complete image (Data) or the structured form: ByteSize (SII word
// 0x3E), ConfigData (words 0-6, the ESC configuration area), BootStrap (words 0x14-0x17) and
// extra Categories.
#include <string>

#include "check/areas.hpp"
#include "check/rule_cache.hpp"
#include "check/queries.hpp"
#include "esi/number.hpp"

namespace esi::rules {

namespace {

constexpr std::size_t config_data_max_bytes = 14;  // words 0..6; word 7 is the checksum
constexpr std::size_t boot_strap_bytes = 8;        // 4 words: receive offset/size, send offset/size

std::string device_label(const Device& device) {
    return device.type.text.empty() ? std::string("Device") : "Device '" + device.type.text + "'";
}

// ---- eeprom-data-and-structured -------------------------------------------------------------

void check_data_and_structured(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->eeprom || !device->eeprom->data) continue;
        const Eeprom& e = *device->eeprom;
        std::string also;
        auto add = [&](bool present, const char* name) {
            if (!present) return;
            also += also.empty() ? name : std::string(", ") + name;
        };
        add(e.byte_size_pos.known(), "ByteSize");
        add(e.config_data.has_value(), "ConfigData");
        add(e.boot_strap.has_value(), "BootStrap");
        add(!e.categories.empty(), "Category");
        if (also.empty()) continue;
        context.report(e.data->pos, device_label(*device) + ": Eeprom has a complete image (Data) and also " + also +
                                        "; tools use either the image as it is or build one from the structured "
                                        "elements, so one of them is silently ignored");
    }
}

constexpr Rule eeprom_data_and_structured{
    .id = "eeprom-data-and-structured",
    .default_severity = Severity::error,
    .summary = "Eeprom with both a raw Data image and structured elements",
    .rationale =
        "Eeprom is a choice: either Data, the complete SII image used as it is, or "
        "ByteSize/ConfigData/BootStrap/Category from which a tool builds the image (ETG.2000 EepromType; "
        "leducp/KickCAT rejects 'Eeprom with both Data and ByteSize'). With both, one half is silently ignored, and "
        "which half differs between tools.",
    .bad_example =
        "<Eeprom><Data>050E0344...</Data><ByteSize>2048</ByteSize><ConfigData>050E0344</ConfigData></Eeprom>",
    .good_example = "<Eeprom><ByteSize>2048</ByteSize><ConfigData>050E03440A000000</ConfigData></Eeprom>",
    .check = check_data_and_structured,
};

// ---- eeprom-byte-size -----------------------------------------------------------------------

void check_byte_size(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->eeprom || !device->eeprom->byte_size) continue;
        const std::uint32_t size = *device->eeprom->byte_size;
        if (size != 0 && size % 128 == 0 && size / 128 <= 0x10000) continue;
        std::string message = device_label(*device) + ": Eeprom ByteSize " + std::to_string(size);
        if (size == 0) message += " is 0";
        else if (size % 128 != 0) message += " is not a multiple of 128";
        else message += " is larger than SII word 0x3E can express (8 MiB)";
        message += "; SII word 0x3E stores the size as (bytes / 128) - 1, i.e. in KiBit minus one";
        if (size % 128 != 0 && size > 128) message += " (nearest: " + std::to_string(size / 128 * 128) + ")";
        context.report(device->eeprom->byte_size_pos, std::move(message));
    }
}

constexpr Rule eeprom_byte_size{
    .id = "eeprom-byte-size",
    .default_severity = Severity::error,
    .summary = "Eeprom ByteSize that SII word 0x3E cannot express",
    .rationale =
        "SII word 0x3E holds the EEPROM size as KiBit minus one, i.e. bytes / 128 - 1 (ETG.2010; Beckhoff ESC datasheet "
        "'SII EEPROM content'). A ByteSize of 0 or one that is not a multiple of 128 cannot be written there, and the "
        "conformance tool compares ByteSize with that word (CTT TF-1300 2-6).",
    .bad_example = "<Eeprom><ByteSize>2000</ByteSize><ConfigData>050E0344</ConfigData></Eeprom>",
    .good_example = "<Eeprom><ByteSize>2048</ByteSize><ConfigData>050E0344</ConfigData></Eeprom>",
    .check = check_byte_size,
};

// ---- eeprom-byte-size-unusual ---------------------------------------------------------------

void check_byte_size_unusual(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->eeprom || !device->eeprom->byte_size) continue;
        const std::uint32_t size = *device->eeprom->byte_size;
        if (size == 0 || size % 128 != 0 || (size & (size - 1)) == 0) continue;  // eeprom-byte-size or fine
        std::uint32_t below = 128;
        while (below * 2 <= size) below *= 2;
        context.report(device->eeprom->byte_size_pos,
                       device_label(*device) + ": Eeprom ByteSize " + std::to_string(size) +
                           " is not a power of two, which no serial EEPROM part has (" +
                           std::to_string(below) + " or " + std::to_string(below * 2) +
                           " would be); keep it only for an emulated EEPROM of exactly this size");
    }
}

constexpr Rule eeprom_byte_size_unusual{
    .id = "eeprom-byte-size-unusual",
    .default_severity = Severity::info,
    .summary = "Eeprom ByteSize that is not a power of two",
    .rationale =
        "SII EEPROMs are serial parts of 2^n bytes (1 KiBit = 128 bytes up to 16 KiBit = 2048 bytes and beyond); a "
        "size such as 1920 fits SII word 0x3E but matches no part, and tools that size images by it write or check "
        "the wrong range (CTT TF-1300 2-6; MetalMusings/MyOwnEtherCATDevice #16 'file length is larger than chip "
        "capacity'). Emulated EEPROMs (in an MCU or FPGA) can have other sizes, hence only information.",
    .bad_example = "<Eeprom><ByteSize>1920</ByteSize><ConfigData>050E0344</ConfigData></Eeprom>",
    .good_example = "<Eeprom><ByteSize>2048</ByteSize><ConfigData>050E0344</ConfigData></Eeprom>",
    .check = check_byte_size_unusual,
};

// ---- eeprom-hex -----------------------------------------------------------------------------

void report_bad_hex(const HexData& data, std::string_view what, const Device& device, SourcePos fallback,
                    RuleContext& context) {
    if (data.valid()) return;
    const bool odd = data.text.size() % 2 != 0;
    std::string shown = data.text.size() > 24 ? data.text.substr(0, 24) + "..." : data.text;
    context.report(data.pos.known() ? data.pos : fallback,
                   device_label(device) + ": Eeprom " + std::string(what) + " '" + shown + "' " +
                       (odd ? "has an odd number of hex digits (" + std::to_string(data.text.size()) + ")"
                            : std::string("contains characters that are not hex digits")) +
                       "; hexBinary needs two hex digits per byte");
}

void check_hex(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->eeprom) continue;
        const Eeprom& e = *device->eeprom;
        if (e.data) report_bad_hex(*e.data, "Data", *device, e.pos, context);
        if (e.config_data) report_bad_hex(*e.config_data, "ConfigData", *device, e.pos, context);
        if (e.boot_strap) report_bad_hex(*e.boot_strap, "BootStrap", *device, e.pos, context);
        for (const auto& cat : e.categories)
            if (cat.data) report_bad_hex(*cat.data, "Category Data", *device, cat.pos, context);
    }
}

constexpr Rule eeprom_hex{
    .id = "eeprom-hex",
    .default_severity = Severity::error,
    .summary = "Eeprom Data, ConfigData, BootStrap or Category Data that is not hexBinary",
    .rationale =
        "These elements are xs:hexBinary: two hex digits per byte. An odd number of digits or a stray character "
        "leaves the bytes undefined; SII writers differ in padding or truncating them (ETG.2000 EepromType; "
        "leducp/KickCAT 'odd-length hex binary'; synapticon/siitool PR #6 fixed its ConfigData scanf).",
    .bad_example = "<Eeprom><ByteSize>2048</ByteSize><ConfigData>050E034</ConfigData></Eeprom>",
    .good_example = "<Eeprom><ByteSize>2048</ByteSize><ConfigData>050E0344</ConfigData></Eeprom>",
    .check = check_hex,
};

// ---- eeprom-config-data ---------------------------------------------------------------------

void check_config_data(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->eeprom || !device->eeprom->config_data || !device->eeprom->config_data->valid()) continue;
        const HexData& data = *device->eeprom->config_data;
        const std::size_t bytes = data.byte_length();
        if (bytes <= config_data_max_bytes) continue;
        context.report(data.pos, device_label(*device) + ": Eeprom ConfigData has " + std::to_string(bytes) +
                                     " bytes; it fills SII words 0-6 (14 bytes), and word 7 is the checksum that tools "
                                     "compute, so bytes beyond 14 overwrite the checksum or the identity words");
    }
}

constexpr Rule eeprom_config_data{
    .id = "eeprom-config-data",
    .default_severity = Severity::error,
    .summary = "Eeprom ConfigData longer than 14 bytes",
    .rationale =
        "ConfigData is the ESC configuration area, SII words 0-6 (PDI control and configuration, SYNC pulse length, "
        "extended PDI configuration, station alias, two reserved words); word 7 is a CRC-8 over these 14 bytes that "
        "tools compute (Beckhoff ESC datasheet section I table 'ESC configuration area'; ETG.2010; CTT TF-1300 2-8). "
        "Longer ConfigData runs into the checksum and the identity words.",
    .bad_example = "<ConfigData>050E03440A0000000000000000000000</ConfigData>",
    .good_example = "<ConfigData>050E03440A000000000000000000</ConfigData>",
    .check = check_config_data,
};

// ---- eeprom-pdi-off --------------------------------------------------------------------------

void check_pdi_off(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->eeprom || !device->eeprom->config_data) continue;
        const auto bytes = device->eeprom->config_data->bytes();
        if (!bytes || bytes->empty() || (*bytes)[0] != 0) continue;
        // Device emulation (0x0141 bit 0): the ESC answers the state machine itself, as couplers
        // without a microcontroller do (EK1100: ConfigData 0001); no PDI is needed then.
        if (bytes->size() > 1 && ((*bytes)[1] & 0x01) != 0) continue;
        const bool mailbox = device->mailbox.has_value();
        const bool process_data = !device->rx_pdos.empty() || !device->tx_pdos.empty();
        if (!mailbox && !process_data) continue;
        context.report(device->eeprom->config_data->pos,
                       device_label(*device) + ": Eeprom ConfigData sets PDI control (SII word 0, register 0x0140) to 0, " +
                           "which switches the process data interface off, and the ESC does not emulate the device " +
                           "(0x0141 bit 0 clear); the device has " +
                           (mailbox && process_data ? "a mailbox and process data" : mailbox ? "a mailbox" : "process data") +
                           ", which only a microcontroller behind the PDI can serve. Set the PDI the board uses " +
                           "(0x05 SPI, 0x08/0x09 µC, 0x80 on-chip bus …; YAML sources: `esc:`)");
    }
}

constexpr Rule eeprom_pdi_off{
    .id = "eeprom-pdi-off",
    .default_severity = Severity::error,
    .summary = "Eeprom ConfigData that switches the PDI off on a device with a mailbox or process data",
    .rationale =
        "The ESC loads SII word 0 into PDI control (0x0140) and ESC configuration (0x0141) at power-on (Beckhoff ESC "
        "datasheet section II 'PDI Control'; ETG.1000.6 Table 16). PDI control 0 leaves the microcontroller without "
        "any access to the ESC: the mailbox is never answered and the state machine stays in INIT unless the ESC "
        "emulates the device (0x0141 bit 0, devices without a microcontroller). Such an image looks consistent to "
        "every offline check and fails only on the bench. Published vendor catalogues (Beckhoff, Microchip, ASIX, the "
        "SOES samples) do not have it, so it is an error.",
    .bad_example = "<Eeprom><ByteSize>2048</ByteSize><ConfigData>0000000000000000</ConfigData></Eeprom>",
    .good_example = "<Eeprom><ByteSize>2048</ByteSize><ConfigData>050E034464000000</ConfigData></Eeprom>",
    .check = check_pdi_off,
};

// ---- eeprom-boot-strap ----------------------------------------------------------------------

void check_boot_strap(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->eeprom || !device->eeprom->boot_strap || !device->eeprom->boot_strap->valid()) continue;
        const HexData& data = *device->eeprom->boot_strap;
        if (data.byte_length() == boot_strap_bytes) continue;
        context.report(data.pos, device_label(*device) + ": Eeprom BootStrap has " + std::to_string(data.byte_length()) +
                                     " bytes; it must be exactly 8 (SII words 0x14-0x17: bootstrap receive mailbox "
                                     "offset and size, send mailbox offset and size)");
    }
}

constexpr Rule eeprom_boot_strap{
    .id = "eeprom-boot-strap",
    .default_severity = Severity::error,
    .summary = "Eeprom BootStrap that is not exactly 8 bytes",
    .rationale =
        "BootStrap holds SII words 0x14-0x17: bootstrap receive mailbox offset and size, send mailbox offset and size "
        "(ETG.2010; Beckhoff ESC datasheet section I, Table 38 SII EEPROM content). Another length shifts or "
        "truncates these words, and firmware that compares them with its boot constants refuses BOOT (SOES soes/esc.c "
        "ESC_startmbxboot: AL status 0x0015 ALERR_INVALIDBOOTMBXCONFIG; kubabuda/EEPROM_generator #3).",
    .bad_example = "<BootStrap>00108000801080</BootStrap>",
    .good_example = "<BootStrap>0010800080108000</BootStrap>",
    .check = check_boot_strap,
};

// ---- eeprom-boot-mailbox-overlap ------------------------------------------------------------

void check_boot_mailbox_overlap(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->eeprom || !device->eeprom->boot_strap) continue;
        const HexData& data = *device->eeprom->boot_strap;
        const auto bytes = data.bytes();
        if (!bytes || bytes->size() != boot_strap_bytes) continue;  // eeprom-hex's or eeprom-boot-strap's
        const auto word = [&](std::size_t i) { return std::uint32_t((*bytes)[2 * i]) | std::uint32_t((*bytes)[2 * i + 1]) << 8; };
        const std::uint32_t out_start = word(0), out_size = word(1), in_start = word(2), in_size = word(3);
        if (out_size == 0 || in_size == 0) continue;  // a direction without boot mailbox
        if (out_start + out_size <= in_start || in_start + in_size <= out_start) continue;
        const auto range = [](std::uint32_t start, std::uint32_t size) {
            return format_hex(start, 4) + ".." + format_hex(start + size - 1, 4);
        };
        context.report(data.pos, device_label(*device) + ": the boot mailboxes of BootStrap overlap: out (master -> slave) " +
                                     range(out_start, out_size) + ", in (slave -> master) " + range(in_start, in_size) +
                                     "; in BOOT the master places SM0 and SM1 there, and the ESC would let them share memory");
    }
}

constexpr Rule eeprom_boot_mailbox_overlap{
    .id = "eeprom-boot-mailbox-overlap",
    .default_severity = Severity::error,
    .summary = "Eeprom BootStrap whose receive and send boot mailboxes overlap",
    .rationale =
        "BootStrap gives the boot mailboxes as SII words 0x14-0x17: receive (master -> slave) offset and size, send "
        "offset and size (ETG.2010). For BOOT the master programs SM0 and SM1 with them instead of the standard "
        "mailbox, so two overlapping ranges make the two SyncManagers share memory, as sm-overlap reports for the "
        "standard ones: a firmware download over FoE corrupts its own answers, and firmware that checks the SM "
        "configuration refuses the BOOT state (AL status 0x0015 invalid boot mailbox configuration). A size of 0 "
        "leaves that direction unused and is not compared.",
    .bad_example = "<BootStrap>0010000200110002</BootStrap> (out #x1000..#x11FF, in #x1100..#x12FF)",
    .good_example = "<BootStrap>0010000200120002</BootStrap> (out #x1000..#x11FF, in #x1200..#x13FF)",
    .check = check_boot_mailbox_overlap,
};

// ---- eeprom-category ------------------------------------------------------------------------

void check_category(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        if (!device->eeprom) continue;
        for (const auto& cat : device->eeprom->categories) {
            const bool has_cat_no = cat.cat_no_pos.known();
            const bool has_payload = cat.data || cat.data_string || cat.data_uint || cat.data_udint;
            if (has_cat_no && has_payload) continue;
            std::string message = device_label(*device) + ": Eeprom Category ";
            if (has_cat_no) message += std::to_string(cat.cat_no) + " ";
            if (!has_cat_no && !has_payload) message += "has neither CatNo nor a payload";
            else if (!has_cat_no) message += "has no CatNo, so tools cannot write its category header";
            else message += "has no payload (Data, DataString, DataUINT or DataUDINT)";
            context.report(cat.pos, std::move(message));
        }
    }
}

constexpr Rule eeprom_category{
    .id = "eeprom-category",
    .default_severity = Severity::error,
    .summary = "Eeprom Category without CatNo or without payload",
    .rationale =
        "An extra SII category needs its type (CatNo, the category header word) and its content (Data, DataString, "
        "DataUINT or DataUDINT); without either, tools cannot write it (ETG.2000 EepromType Category; ETG.2010 "
        "category layout; leducp/KickCAT 'Eeprom Category without payload').",
    .bad_example = "<Category><CatNo>2048</CatNo></Category>",
    .good_example = "<Category><CatNo>2048</CatNo><Data>0100</Data></Category>",
    .check = check_category,
};

// ---- eeprom-physics-port --------------------------------------------------------------------

// The SII General category has a 4-bit port type for each of 4 ports (ETG.2010: 0 not used,
// 1 MII, 2 reserved, 3 E-Bus); the ESI names them with one letter each.
constexpr std::size_t sii_ports = 4;

// B is no letter of ETG.2000's pattern, but the Beckhoff schemas of 2011 and before allowed it
// ([Y,K, ,B]) and Beckhoff's own files of that time use it (EK1200 "BK"): a file valid for its
// schema is not reported for it.
bool is_port_letter(char letter) { return letter == 'Y' || letter == 'H' || letter == 'K' || letter == ' ' || letter == 'B'; }

void check_physics_port(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document)) {
        const std::string& physics = device->physics;
        if (physics.size() > sii_ports)
            context.report(device->pos, device_label(*device) + ": Physics \"" + excerpt(physics) + "\" names " +
                                            std::to_string(physics.size()) + " ports; the SII General category has room for " +
                                            std::to_string(sii_ports) + ", so the others are lost");
        for (std::size_t port = 0; port < physics.size() && port < sii_ports; ++port)
            if (!is_port_letter(physics[port])) {
                context.report(device->pos, device_label(*device) + ": Physics \"" + excerpt(physics) + "\" gives port " +
                                                std::to_string(port) + " the letter '" + std::string(1, physics[port]) +
                                                "', which is not Y, H (MII), K (E-Bus) or a space (none) in any ETG schema; "
                                                "the SII port type is written as not used");
                break;  // one finding per device
            }
    }
}

constexpr Rule eeprom_physics_port{
    .id = "eeprom-physics-port",
    .default_severity = Severity::warning,
    .summary = "Device@Physics with a letter other than Y, H, K or space, or more than 4 ports",
    .rationale =
        "Physics names each port's physical layer, one letter per port: Y or H for MII (100BASE-TX), K for E-Bus "
        "(LVDS), a space for no port (ETG.2000 PhysicsType, pattern [Y,K,H, ]{0,4}). SII builders turn the letters into "
        "the 4-bit port types of the General category (ETG.2010 PhysicalPort: not used, MII, E-Bus), which the "
        "conformance test compares with the description (CTT TF-1300 1-3 'ESI Port Type Consistency'). Another "
        "letter has no port type: esi-sii build writes the port as not used (sii-physics), so the image and the "
        "description disagree; a fifth port has no field at all. Masters take the topology from the ESC's DL status, "
        "not from these fields: a warning. B, which the Beckhoff schemas of 2011 and before allowed ([Y,K, ,B]) and "
        "their files of that time use (EK1200 'BK'), is not reported. Without --xsd no other rule sees the letters.",
    .bad_example = "<Device Physics=\"KX\">",
    .good_example = "<Device Physics=\"KK\">",
    .check = check_physics_port,
};

}  // namespace

void add_eeprom(std::vector<Rule>& out) {
    out.insert(out.end(), {
        eeprom_data_and_structured,
        eeprom_byte_size,
        eeprom_byte_size_unusual,
        eeprom_hex,
        eeprom_config_data,
        eeprom_pdi_off,
        eeprom_boot_strap,
        eeprom_boot_mailbox_overlap,
        eeprom_category,
        eeprom_physics_port,
    });
}

}  // namespace esi::rules
