#pragma once
// The model -> YAML tree half of the importer (import.cpp decides what derivation may
// reproduce; this writes what is left). One function per part of docs/yaml-format.md, in files
// that mirror the parser's: import_common.cpp, import_dictionary.cpp, import_mailbox.cpp,
// import_device.cpp, import_module.cpp.

#include <cstdint>
#include <string>
#include <vector>

#include "esi/derive/derive.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/esc_preset.hpp"
#include "esi/model/passive_terminal.hpp"
#include "esi/model/ethercat_info.hpp"
#include "import/yaml_emitter.hpp"

namespace esi::import_detail {

// Which derived parts of one device are left out of the YAML (and derived again on load).
// Everything false: the device is written completely, with `derive: false`.
struct OmitPlan {
    bool data_link_layer = false;  // Mailbox@DataLinkLayer = true
    bool sms = false;              // SyncManagers (mailbox sizes go to `mailbox`)
    bool fmmus = false;
    bool pdo_assignment = false;   // RxPdo/TxPdo@Sm of the default assignment
    bool pdo_entries = false;      // Entry BitLen/DataType/Name
    bool device_type_object = false;   // 0x1000
    bool identity_object = false;      // 0x1018
    bool mapping_objects = false;      // 0x16xx/0x1Axx
    bool assignment_objects = false;   // 0x1C1x
    bool sm_types_object = false;      // 0x1C00
    bool data_types = false;           // DataTypes derivation reproduces

    [[nodiscard]] bool any() const {
        return data_link_layer || sms || fmmus || pdo_assignment || pdo_entries || device_type_object || identity_object ||
               mapping_objects || assignment_objects || sm_types_object || data_types;
    }
    [[nodiscard]] DeriveOptions derive_options() const;
};

class ImportWriter {
public:
    explicit ImportWriter(Diagnostics& warnings) : warnings_(warnings) {}

    YNode vendor(const Vendor& v);
    YNode group(const Group& g);
    YNode device(const Device& d, const EtherCATInfo& info, const OmitPlan& plan);
    YNode module(const Module& m);
    YNode extras(const Extras& e);

    // Warnings are suppressed while a trial import runs (import.cpp tries plans).
    bool quiet = false;

private:
    void warn(const std::string& path, const std::string& message);
    void names(YNode& map, std::string_view key, const Names& names, const std::string& path, bool required = false);
    void images(YNode& map, const Images& images);
    void set_extras(YNode& map, std::string_view key, const Extras& e);
    YNode profile(const Profile& p);
    void dictionary(YNode& map, const Dictionary& d, const std::string& path, const OmitPlan& plan, const Device* device);
    YNode data_type(const DataType& t, const std::string& path);
    YNode object(const Object& o, const Dictionary& d, const std::string& path);
    void flags(YNode& map, const ObjectFlags& f, const std::string& path, std::string_view xml_key);
    void info(YNode& map, const ObjectInfo& info, const Dictionary* d, const std::string& type, const std::string& path,
              bool typed_limits);
    YNode mailbox(const Mailbox& m, const Device* device, const OmitPlan& plan, const std::string& path);
    YNode init_cmd(const InitCmd& c, MailboxProtocol protocol, const std::string& path);
    YNode pdo(const Pdo& p, const OmitPlan& plan, const std::string& path);
    YNode pdo_entry(const PdoEntry& e, const OmitPlan& plan, const std::string& path);
    YNode dc(const Dc& dc);
    YNode dc_time(const DcTime& t);
    YNode slots(const Slots& s, const std::string& path);
    YNode eeprom(const Eeprom& e, const std::string& path);  // without what `esc:` stands for
    static const EscPreset* esc_preset_of(const Eeprom& e);

    Diagnostics& warnings_;
};

// Shared by the import_*.cpp files (defined in import_common.cpp).
std::string hex_text(std::uint64_t v, int digits);  // 0x00AB for (0xAB, 4)
YNode hex_data(const HexData& h);
bool valid_hex(const HexData& h);  // an even number of hex digits
std::string child(const std::string& path, const std::string& name);  // the model path `path/name`

}  // namespace esi::import_detail
