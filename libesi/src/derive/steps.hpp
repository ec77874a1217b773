#pragma once
// The derivation steps derive_device() runs, in order. Each fills in one concern and leaves
// explicit values alone. Internal to libesi.

#include <map>
#include <string>
#include <vector>

#include "esi/derive/derive.hpp"

namespace esi::derive {

class Context {
public:
    Context(const std::string& path, Diagnostics& diagnostics) : path_(path), diagnostics_(diagnostics) {}
    Diagnostic& error(SourcePos pos, std::string rule, std::string message) {
        return diagnostics_.emplace(Severity::error, std::move(rule), std::move(message), path_, pos);
    }
    Diagnostic& warning(SourcePos pos, std::string rule, std::string message) {
        return diagnostics_.emplace(Severity::warning, std::move(rule), std::move(message), path_, pos);
    }
    [[nodiscard]] const std::string& path() const { return path_; }

private:
    const std::string& path_;
    Diagnostics& diagnostics_;
};

// SM numbers that carry process data, as the derived or explicit SM list will have them.
struct SmPlan {
    std::optional<std::uint32_t> outputs;  // the SM RxPDOs are assigned to
    std::optional<std::uint32_t> inputs;   // the SM TxPDOs are assigned to
};

[[nodiscard]] std::string hex4(std::uint32_t value);  // "0x1600"

// The dictionary objects go to: the first Profile's, created when the device has CoE or objects.
Dictionary* dictionary_of(Device& device, bool create);
[[nodiscard]] std::map<std::uint32_t, const Object*> object_index(const Dictionary& dictionary);

void derive_standard_objects(Device& device, const DeviceIntent& intent, Context& context);
void derive_pdo_entries(std::vector<Pdo>& pdos, const Dictionary* dictionary, Context& context);
[[nodiscard]] SmPlan plan_sms(const Device& device, const DeviceIntent& intent);
void derive_pdo_assignment(Device& device, const DeviceIntent& intent, const SmPlan& plan, Context& context);
void derive_sync_managers(Device& device, const DeviceIntent& intent, Context& context);
void derive_fmmus(Device& device);
void derive_mapping_objects(Device& device, const DeviceIntent& intent, Context& context);
void derive_assignment_objects(Device& device, Context& context);
void derive_sm_types_object(Device& device, Context& context);
void derive_init_values(std::vector<InitCmd>& init_cmds, const std::vector<InitCmdValue>& values, const Dictionary* dictionary,
                        Context& context);
void derive_data_types(Dictionary& dictionary, Context& context);
void sort_objects(Dictionary& dictionary);

}  // namespace esi::derive
