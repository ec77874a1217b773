#pragma once
// YAML device source -> model (before derivation). One class, split over parse_*.cpp by part of
// the format: common pieces, PDOs, the object dictionary and its DataTypes, devices, modules and
// slots. The format is
// documented in docs/yaml-format.md; the keys of every mapping are in format_keys.cpp.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "esi/yaml/tree.hpp"

#include "esi/derive/derive.hpp"
#include "esi/device_selector.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/model/typed_value.hpp"
#include "esi/source_text.hpp"
#include "esi/yaml/reader.hpp"

namespace esi::yaml {

// Objects by name, for PDO entries and InitCmds that name an object instead of its index.
struct ObjectNames {
    struct Target {
        std::uint32_t index = 0;
        bool is_var = true;
        std::vector<std::uint32_t> ambiguous_with;  // other indices with the same name
    };
    std::map<std::string, Target, std::less<>> by_name;
};

// An object reference as written: 0x6040, "0x6041:1", "Controlword".
struct ObjectRef {
    std::uint32_t index = 0;
    std::optional<std::uint32_t> subindex;  // written as "index:subindex"
    bool names_record = false;              // a record named by its name: the sub-index must follow
};

struct ParsedDevice {
    Device device;
    DeviceIntent intent;
    std::optional<Limits> limits;
};

struct ParsedModule {
    Module module;
    ModuleIntent intent;
};

class SourceParser {
public:
    SourceParser(Reader& reader, const SourceText& source) : r_(reader), source_(source) {}

    // The whole file; nullopt when the root is not a mapping.
    std::optional<EtherCATInfo> parse(const Node& root, std::vector<ParsedDevice>& devices,
                                      std::vector<ParsedModule>& modules);
    // The source declared `root_element: EtherCATModule`.
    [[nodiscard]] bool module_file() const { return module_file_; }

private:
    // ---- parse_common.cpp --------------------------------------------------------------------
    void images(const Fields& f, Images& out);
    void extras(const Fields& f, std::string_view key, Extras& out);
    Names names_of(const Fields& f, std::string_view key);
    std::optional<ObjectRef> object_ref(const Node& node, const ObjectNames& names, std::string_view what);
    std::optional<std::vector<Transition>> transitions(const Node& node);
    DeriveOptions derive_options(const Node& node, bool module);
    std::optional<Profile> profile(const Node& node);
    void init_cmds(const Node& node, MailboxProtocol protocol, const ObjectNames& names, std::vector<InitCmd>& out,
                   std::vector<InitCmdValue>* values);
    std::optional<Mailbox> mailbox(const Node& node, Context context, MailboxLayout* layout, const ObjectNames& names);

    // ---- parse_pdos.cpp ----------------------------------------------------------------------
    std::vector<Pdo> pdos(const Node& node, PdoDirection direction, const ObjectNames& names, std::vector<bool>* assign);
    std::optional<PdoEntry> pdo_entry(const Node& node, const ObjectNames& names);

    // ---- parse_dictionary.cpp ----------------------------------------------------------------
    // Reads data_types and objects into `dictionary`; returns the names of the objects.
    ObjectNames dictionary(const Fields& f, Dictionary& dictionary);
    std::optional<ObjectSubItemInfo> info_sub_item(const Node& node);
    void object(const Node& key, const Node& value, Dictionary& dictionary,
                std::map<std::uint32_t, std::pair<SourcePos, std::string>>& seen);
    std::optional<ObjectFlags> flags(const Fields& f);
    std::optional<ObjectInfo> info(const Fields& f, const Dictionary& dictionary, const std::string& type_name,
                                   std::string_view what);
    std::optional<Number> typed_integer(const Node& node, const Dictionary& dictionary, const std::string& type_name,
                                        std::string_view what);

    // ---- parse_data_types.cpp ----------------------------------------------------------------
    std::optional<DataType> data_type(const Node& node);
    bool enum_texts(const Node& value, EnumValue& ev);

    // ---- parse_device.cpp --------------------------------------------------------------------
    std::optional<ParsedDevice> device(const Node& node, std::optional<std::uint32_t> vendor_id,
                                       const std::vector<ParsedModule>& modules, std::size_t group_count,
                                       const std::string* only_group);
    std::optional<Eeprom> eeprom(const Node& node);
    void esc_preset(const Node& node, Device& d);  // `esc:` fills what `eeprom:` leaves out
    std::vector<SyncManager> sync_managers(const Node& node, std::vector<SourcePos>& size_pos);
    std::vector<Fmmu> fmmus(const Node& node);
    std::vector<SyncUnit> sync_units(const Node& node);
    std::optional<Dc> dc(const Node& node);
    std::optional<DcTime> dc_time(const Node& node, bool shift);
    Limits limits(const Node& node);

    // ---- parse_module.cpp --------------------------------------------------------------------
    std::optional<ParsedModule> module(const Node& node);
    std::optional<Slots> slots(const Node& node, const std::vector<ParsedModule>& modules);
    std::optional<std::uint32_t> module_ident(const Node& node, const std::vector<ParsedModule>& modules,
                                              std::string_view what);

    // ---- source.cpp ---------------------------------------------------------------------------
    std::optional<Vendor> vendor(const Node& node);
    std::optional<Group> group(const Node& node);

    Reader& r_;
    const SourceText& source_;
    bool module_file_ = false;
};

// Objects a device or module declares, indexed by primary name (ambiguous names are marked).
ObjectNames index_object_names(const Dictionary& dictionary);

// An index as messages spell it: 0x6040 (parse_common.cpp).
std::string hex4(std::uint32_t v);

// What a value of type `type_name` in `dictionary` is: basic type, size, enumeration
// (parse_dictionary.cpp).
ValueType value_type_of(const Dictionary& dictionary, const std::string& type_name);

}  // namespace esi::yaml
