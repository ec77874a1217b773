// The host program of the SOES tests (tests/sim_soes): virtual slaves on a network interface, as
// esi-sim serves them, where a device's firmware is the real SOES stack built from esi-gen's SOES
// set (firmware/: one shared object per device, loaded with dlopen) instead of esi-sim's model
// slave. Test code only (SOES is GPL with a linking exception and never shipped).
//
//   esi_soes_host --iface IF SOURCE [--device SEL] [--eeprom FILE] --firmware [SEL=]LIB.so ...
//
// SOURCE is a device source (one slave) or esi-net's NETWORK.yaml; a --firmware without SEL runs
// on every slave, with SEL (PRODUCTCODE[:REVISION]) on the slaves of that device; the others
// run the model slave. The SOES slaves' input objects (those any TxPDO of the model maps) hold
// a fixed pattern; on SIGTERM the program prints a JSON report on stdout: per SOES slave its AL
// status, the input values it set and the output objects' values of its last poll in OP.
#include <dlfcn.h>
#include <signal.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "esi/device_selector.hpp"
#include "esi/sim/model_slave.hpp"
#include "esi/sim/raw_socket.hpp"
#include "esi/sim/slave_setup.hpp"
#include "../firmware/soes_firmware.h"

namespace {

std::atomic<bool> stop_requested{false};
extern "C" void request_stop(int) { stop_requested.store(true); }

struct Firmware {
    std::optional<esi::DeviceSelector> selector;
    std::filesystem::path library;
};

struct ObjectRef {
    std::uint16_t index = 0;
    std::uint8_t subindex = 0;
};

// The value the host puts into an input object: every bit position of the object's width used,
// different per object, so a byte or bit out of place at the master shows.
std::uint64_t input_pattern(const ObjectRef& o) {
    std::uint64_t x = (std::uint64_t{o.index} << 8 | o.subindex) * 0x9E3779B97F4A7C15ull;
    x ^= x >> 29;
    return x * 0xBF58476D1CE4E5B9ull;
}

std::vector<ObjectRef> mapped_objects(const std::vector<esi::Pdo>& pdos) {
    std::vector<ObjectRef> out;
    for (const esi::Pdo& pdo : pdos)
        for (const esi::PdoEntry& e : pdo.entries) {
            if (e.is_padding()) continue;
            const ObjectRef ref{static_cast<std::uint16_t>(e.index), static_cast<std::uint8_t>(e.subindex.value_or(0))};
            bool seen = false;
            for (const ObjectRef& r : out) seen = seen || (r.index == ref.index && r.subindex == ref.subindex);
            if (!seen) out.push_back(ref);
        }
    return out;
}

// One SOES instance: a private copy of the firmware library (SOES's state is global, so two
// slaves need two copies), its entry points, and what the test reads back.
class SoesStack final : public esi::esc::SlaveStack {
public:
    SoesStack(void* handle, std::string name, std::vector<ObjectRef> inputs, std::vector<ObjectRef> outputs,
              std::vector<std::uint8_t> eeprom)
        : handle_(handle), name_(std::move(name)), inputs_(std::move(inputs)), outputs_(std::move(outputs)),
          eeprom_(std::move(eeprom)) {
        attach_ = reinterpret_cast<decltype(attach_)>(dlsym(handle, "esi_soes_attach"));
        init_ = reinterpret_cast<decltype(init_)>(dlsym(handle, "esi_soes_init"));
        run_ = reinterpret_cast<decltype(run_)>(dlsym(handle, "esi_soes_run"));
        status_ = reinterpret_cast<decltype(status_)>(dlsym(handle, "esi_soes_al_status"));
        get_ = reinterpret_cast<decltype(get_)>(dlsym(handle, "esi_soes_get"));
        set_ = reinterpret_cast<decltype(set_)>(dlsym(handle, "esi_soes_set"));
        output_values_.assign(outputs_.size(), std::nullopt);
    }
    ~SoesStack() override { dlclose(handle_); }

    [[nodiscard]] bool complete() const { return attach_ && init_ && run_ && status_ && get_ && set_; }

    void poll(esi::esc::Pdi& pdi) override {
        const esi_soes_pdi bound{&pdi, &read, &write, eeprom_.empty() ? nullptr : eeprom_.data(),
                                 static_cast<std::uint32_t>(eeprom_.size())};
        attach_(&bound);
        if (!started_) {
            init_();
            started_ = true;
        }
        for (const ObjectRef& o : inputs_) set_(o.index, o.subindex, input_pattern(o));
        run_();
        if ((status_() & 0x0F) == 0x08) {
            ++op_polls_;
            for (std::size_t i = 0; i < outputs_.size(); ++i) {
                std::uint64_t value = 0;
                std::uint16_t bits = 0;
                if (get_(outputs_[i].index, outputs_[i].subindex, &value, &bits) == 0) output_values_[i] = value;
            }
        }
    }

    [[nodiscard]] nlohmann::json report() const {
        nlohmann::json r{{"name", name_}, {"al_status", started_ ? status_() : 0}, {"op_polls", op_polls_}};
        r["inputs"] = nlohmann::json::array();
        for (const ObjectRef& o : inputs_) {
            std::uint64_t value = 0;
            std::uint16_t bits = 0;
            const bool found = get_(o.index, o.subindex, &value, &bits) == 0;
            r["inputs"].push_back({{"index", o.index}, {"sub", o.subindex}, {"found", found}, {"bits", bits}, {"value", value}});
        }
        r["outputs"] = nlohmann::json::array();
        for (std::size_t i = 0; i < outputs_.size(); ++i) {
            nlohmann::json o{{"index", outputs_[i].index}, {"sub", outputs_[i].subindex}};
            if (output_values_[i]) o["value"] = *output_values_[i];
            r["outputs"].push_back(o);
        }
        return r;
    }

private:
    static void read(void* context, std::uint16_t address, void* buffer, std::uint16_t length) {
        static_cast<esi::esc::Pdi*>(context)->read(address, {static_cast<std::uint8_t*>(buffer), length});
    }
    static void write(void* context, std::uint16_t address, const void* buffer, std::uint16_t length) {
        static_cast<esi::esc::Pdi*>(context)->write(address, {static_cast<const std::uint8_t*>(buffer), length});
    }

    void* handle_;
    std::string name_;
    std::vector<ObjectRef> inputs_, outputs_;
    std::vector<std::uint8_t> eeprom_;
    std::vector<std::optional<std::uint64_t>> output_values_;
    bool started_ = false;
    std::uint64_t op_polls_ = 0;
    void (*attach_)(const esi_soes_pdi*) = nullptr;
    void (*init_)() = nullptr;
    void (*run_)() = nullptr;
    std::uint8_t (*status_)() = nullptr;
    int (*get_)(std::uint16_t, std::uint8_t, std::uint64_t*, std::uint16_t*) = nullptr;
    int (*set_)(std::uint16_t, std::uint8_t, std::uint64_t) = nullptr;
};

// dlopen of a private copy: the same path twice would give the same (shared) SOES globals.
void* load_copy(const std::filesystem::path& library, const std::filesystem::path& dir, int n, std::string& error) {
    const std::filesystem::path copy = dir / ("firmware-" + std::to_string(n) + ".so");
    std::error_code ec;
    std::filesystem::copy_file(library, copy, std::filesystem::copy_options::overwrite_existing, ec);
    if (ec) {
        error = library.string() + ": " + ec.message();
        return nullptr;
    }
    void* handle = dlopen(copy.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) error = dlerror();
    std::filesystem::remove(copy, ec);
    return handle;
}

}  // namespace

int main(int argc, char** argv) {
    std::string interface, source, device, eeprom_path;
    std::vector<Firmware> firmware;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        if (arg == "--iface" && has_value) interface = argv[++i];
        else if (arg == "--device" && has_value) device = argv[++i];
        else if (arg == "--eeprom" && has_value) eeprom_path = argv[++i];
        else if (arg == "--firmware" && has_value) {
            const std::string value = argv[++i];
            Firmware f;
            const auto eq = value.find('=');
            if (eq != std::string::npos) {
                std::string error;
                f.selector = esi::parse_device_selector(value.substr(0, eq), error);
                if (!f.selector) {
                    std::cerr << "esi_soes_host: --firmware " << value << ": " << error << "\n";
                    return 2;
                }
            }
            f.library = eq == std::string::npos ? value : value.substr(eq + 1);
            firmware.push_back(f);
        } else if (source.empty() && arg.rfind("--", 0) != 0) source = arg;
        else {
            std::cerr << "usage: esi_soes_host --iface IF SOURCE [--device SEL] [--eeprom FILE] --firmware [SEL=]LIB.so\n";
            return 2;
        }
    }
    if (interface.empty() || source.empty()) {
        std::cerr << "esi_soes_host: --iface and SOURCE are required\n";
        return 2;
    }
    std::vector<std::uint8_t> eeprom;
    if (!eeprom_path.empty()) {
        std::ifstream in(eeprom_path, std::ios::binary);
        eeprom.assign(std::istreambuf_iterator<char>(in), {});
    }
    char dir_template[] = "/tmp/esi-soes-host-XXXXXX";
    if (!mkdtemp(dir_template)) {
        std::cerr << "esi_soes_host: cannot make a temporary directory\n";
        return 2;
    }
    const std::filesystem::path dir = dir_template;

    std::vector<SoesStack*> soes_slaves;  // owned by the line
    int loaded = 0;
    bool failed = false;
    const esi::sim::StackFactory factory = [&](const esi::EtherCATInfo& info, const esi::Device& dev,
                                               esi::Diagnostics& diagnostics) -> std::unique_ptr<esi::esc::SlaveStack> {
        for (const Firmware& f : firmware) {
            if (f.selector && !f.selector->matches(dev)) continue;
            std::string error;
            void* handle = load_copy(f.library, dir, loaded++, error);
            if (!handle) {
                std::cerr << "esi_soes_host: " << error << "\n";
                failed = true;
                return nullptr;
            }
            auto stack = std::make_unique<SoesStack>(handle, dev.type.text, mapped_objects(dev.tx_pdos),
                                                     mapped_objects(dev.rx_pdos), eeprom);
            if (!stack->complete()) {
                std::cerr << "esi_soes_host: " << f.library << " lacks the esi_soes_* entry points\n";
                failed = true;
                return nullptr;
            }
            soes_slaves.push_back(stack.get());
            return stack;
        }
        return esi::sim::make_model_slave(info, dev, {}, diagnostics);
    };

    std::string bytes;
    {
        std::ifstream in(source, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    esi::sim::LineResult built;
    if (esi::sim::is_network_file(bytes)) {
        built = esi::sim::line_from_network(source, factory);
    } else {
        esi::sim::SourceOptions options;
        if (!device.empty()) {
            std::string error;
            options.device = esi::parse_device_selector(device, error);
            if (!options.device) {
                std::cerr << "esi_soes_host: --device " << device << ": " << error << "\n";
                return 2;
            }
        }
        if (!eeprom_path.empty()) options.eeprom = eeprom_path;
        built = esi::sim::line_from_source(source, options, factory);
    }
    std::filesystem::remove_all(dir);
    for (const esi::Diagnostic& d : built.diagnostics)
        if (d.severity == esi::Severity::error) std::cerr << "esi_soes_host: " << source << ": " << d.message << "\n";
    if (!built.line || failed) return 2;

    struct sigaction action {};
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    esi::sim::Line& line = *built.line;
    const esi::Diagnostics served = esi::sim::serve_interface(line, interface, stop_requested, [&] {
        std::cerr << "esi_soes_host: " << line.size() << " slave(s) on " << interface << std::endl;
    });
    if (served.has_errors()) {
        for (const esi::Diagnostic& d : served) std::cerr << "esi_soes_host: " << interface << ": " << d.message << "\n";
        return 2;
    }
    nlohmann::json report = nlohmann::json::array();
    for (const SoesStack* s : soes_slaves) report.push_back(s->report());
    std::cout << report.dump() << std::endl;
    return 0;
}
