// The model slave (esi/sim/model_slave.hpp): the AL state machine, the mailbox with its CoE
// server and the process data, on one device model.

#include "esi/sim/model_slave.hpp"

#include <algorithm>

#include "sim/al_checks.hpp"
#include "sim/al_registers.hpp"
#include "sim/al_state_machine.hpp"
#include "sim/coe_dictionary_build.hpp"
#include "sim/mailbox_server.hpp"
#include "sim/process_image.hpp"

namespace esi::sim {

namespace {

class ModelSlave final : public esc::SlaveStack, private AlTransitions {
public:
    ModelSlave(DeviceModel model, DeviceExpectations expected, const ModelSlaveOptions& options)
        : model_(std::move(model)),
          expected_(std::move(expected)),
          options_(options),
          access_(model_.dictionary, access_rules()),
          coe_(access_, coe_flag(&CoeProtocol::sdo_info)) {
        if (expected_.mailbox_out && expected_.mailbox_in)
            mailbox_.emplace(MailboxGeometry{expected_.mailbox_out->number, expected_.mailbox_out->start,
                                             expected_.mailbox_out->length, expected_.mailbox_in->number,
                                             expected_.mailbox_in->start, expected_.mailbox_in->length},
                             has_coe() ? &coe_ : nullptr);
    }

    void poll(esc::Pdi& pdi) override {
        al_.poll(pdi, *this);
        watch_outputs(pdi);
        const AlState state = al_.state();
        if (mailbox_ && (state == AlState::preop || state == AlState::safeop || state == AlState::op)) mailbox_->poll(pdi, state);
        if (state == AlState::safeop || state == AlState::op) exchange_process_data(pdi, state);
    }

private:
    [[nodiscard]] bool has_coe() const { return model_.device.mailbox && model_.device.mailbox->coe; }
    [[nodiscard]] bool coe_flag(std::optional<bool> CoeProtocol::*flag) const {
        return has_coe() && (*model_.device.mailbox->coe.*flag).value_or(false);
    }

    AccessRules access_rules() const {
        AccessRules rules;
        rules.complete_access = coe_flag(&CoeProtocol::complete_access);
        for (const SmExpectation& sm : expected_.sms) rules.sm_roles.push_back(sm.role);
        rules.sm_max_bits = expected_.sm_max_bits;
        return rules;
    }

    // The process-data watchdog of the ESC ran out in OP (the master stopped writing outputs):
    // the outputs go to their safe state, 0, and the device to SAFEOP with the error indication
    // and "SyncManager watchdog" (ETG.1000.6 Table 11), as ETG.1000.6 6.4 has a device do.
    void watch_outputs(esc::Pdi& pdi) {
        if (!(reg::read_u32(pdi, reg::al_event_request) & reg::al_event_watchdog_process_data)) return;
        const bool expired = !(reg::read_u16(pdi, reg::watchdog_status_process_data) & 1);  // clears the event
        if (!expired) return;
        watchdog_expired_ = true;
        if (al_.state() != AlState::op) return;
        outputs_to_safe_state();
        al_.local_error(pdi, AlState::safeop, al_code::sm_watchdog);
    }

    void outputs_to_safe_state() {
        for (const SmProcessData& data : layout_) {
            if (data.role != SmRole::outputs || data.bytes() == 0) continue;
            const std::vector<std::uint8_t> zeros(data.bytes(), 0);
            buffer_to_objects(data, zeros, model_.dictionary);
        }
    }

    std::uint16_t check(esc::Pdi& pdi, AlState from, AlState to) override {
        if (from == AlState::init && to == AlState::preop && expected_.mailbox_out && expected_.mailbox_in)
            return check_mailbox_sms(pdi, *expected_.mailbox_out, *expected_.mailbox_in);
        if (from == AlState::init && to == AlState::boot) {
            if (!expected_.boot_out || !expected_.boot_in) return al_code::bootstrap_not_supported;
            return check_mailbox_sms(pdi, *expected_.boot_out, *expected_.boot_in);
        }
        if (from == AlState::preop && to == AlState::safeop) {
            // The mapping as the master left it in PREOP decides the SM lengths from here on.
            layout_ = lay_out_process_data(model_.dictionary, access_.rules().sm_roles);
            for (const SmProcessData& data : layout_) {
                if (const std::uint16_t code = check_process_sm(pdi, expected_.sms[data.sm], data.bytes()); code != al_code::none)
                    return code;
            }
            return check_dc(pdi, expected_.assign_activate);
        }
        // No OP on outputs that have stopped coming: the master writes them again first (a
        // write rewinds the watchdog and sets its status again).
        if (from == AlState::safeop && to == AlState::op && watchdog_expired_) {
            if (!(reg::read_u16(pdi, reg::watchdog_status_process_data) & 1)) return al_code::sm_watchdog;
            watchdog_expired_ = false;
        }
        return al_code::none;
    }

    void entered(esc::Pdi&, AlState, AlState to) override {
        if (to == AlState::init && mailbox_) mailbox_->reset();
    }

    void exchange_process_data(esc::Pdi& pdi, AlState state) {
        outputs_.clear();
        for (const SmProcessData& data : layout_) {
            if (data.role != SmRole::outputs || data.bytes() == 0) continue;
            std::vector<std::uint8_t> buffer(data.bytes(), 0);
            // Outputs are valid in OP only (ETG.1000.6 6.4.1); in SAFEOP the device keeps its own.
            if (state == AlState::op) {
                pdi.read(expected_.sms[data.sm].start, buffer);
                buffer_to_objects(data, buffer, model_.dictionary);
            } else {
                objects_to_buffer(data, model_.dictionary, buffer);
            }
            outputs_.insert(outputs_.end(), buffer.begin(), buffer.end());
        }
        std::size_t echoed = 0;
        for (const SmProcessData& data : layout_) {
            if (data.role != SmRole::inputs || data.bytes() == 0) continue;
            std::vector<std::uint8_t> buffer(data.bytes(), 0);
            objects_to_buffer(data, model_.dictionary, buffer);
            if (options_.echo) {
                // The outputs, SM after SM, over the inputs, SM after SM, as far as both go.
                for (std::size_t i = 0; i < buffer.size() && echoed < outputs_.size(); ++i) buffer[i] = outputs_[echoed++];
                buffer_to_objects(data, buffer, model_.dictionary);
            }
            pdi.write(expected_.sms[data.sm].start, buffer);
        }
    }

    DeviceModel model_;
    DeviceExpectations expected_;
    ModelSlaveOptions options_;
    ObjectAccess access_;
    CoeServer coe_;
    std::optional<MailboxServer> mailbox_;
    AlStateMachine al_;
    std::vector<SmProcessData> layout_;
    std::vector<std::uint8_t> outputs_;
    bool watchdog_expired_ = false;  // the ESC reported an expiry the outputs have not yet ended
};

}  // namespace

std::unique_ptr<esc::SlaveStack> make_model_slave(const EtherCATInfo& info, const Device& device, const ModelSlaveOptions& options,
                                                  Diagnostics& diagnostics) {
    DeviceExpectations expected = device_expectations(info, device);
    DeviceModel model = build_device_model(info, device, diagnostics);
    std::vector<SmRole> roles;
    for (const SmExpectation& sm : expected.sms) roles.push_back(sm.role);
    fill_sm_types(model.dictionary, roles);
    add_missing_assignment_objects(model.dictionary);
    if (device.mailbox && device.mailbox->coe && (!expected.mailbox_out || !expected.mailbox_in)) {
        diagnostics.emplace(Severity::error, "sim-no-mailbox",
                            "the device declares CoE but no mailbox SyncManagers with a size (MBoxOut and MBoxIn Sm with "
                            "DefaultSize); a master could not reach its CoE server",
                            {}, device.mailbox->pos);
        return nullptr;
    }
    if (device.mailbox && device.mailbox->coe && !model.dictionary_from_model)
        diagnostics.emplace(Severity::info, "sim-derived-dictionary",
                            "the device has no Dictionary: its CoE server answers 0x1000, 0x1018, 0x1C00, the PDO mapping and "
                            "assignment objects and the objects its PDO entries name, as far as they follow from the PDOs",
                            {}, device.pos);
    return std::make_unique<ModelSlave>(std::move(model), std::move(expected), options);
}

}  // namespace esi::sim
