#include "sim_soes/soes_fixtures.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "esi/config_crc.hpp"
#include "esi/load/document.hpp"
#include "support/shell_words.hpp"
#include "support/test_support.hpp"

namespace esi::test {

namespace {

namespace fs = std::filesystem;

fs::path soes_core() { return shared_dir() / "tools" / "soes" / "soes"; }
fs::path firmware_dir() { return source_dir() / "tests" / "sim_soes" / "firmware"; }

// The AddressSanitizer runtime an instrumented firmware needs in the host: none to add when the
// host is instrumented itself (the sanitizer tree), else the compiler's shared runtime, preloaded.
std::string asan_runtime() {
    static const std::string path = [] {
        const RunResult r = run({ESI_SOES_CC, "-print-file-name=libasan.so"});
        std::string p = r.out.substr(0, r.out.find('\n'));
        return r.exit_code == 0 && fs::path(p).is_absolute() && fs::exists(p) ? p : std::string();
    }();
    return path;
}

constexpr bool host_sanitized = ESI_SOES_HOST_SANITIZED != 0;

}  // namespace

std::string soes_unavailable() {
    if (!fs::exists(soes_core() / "esc_coe.c")) return "no SOES stack at " + soes_core().string() + " (../shared/tools/soes)";
    const std::string master = ESI_SOES_MASTER;
    if (master.empty() || !fs::exists(master)) return "the SOEM test master was not built (../shared/tools/soem absent)";
    static const std::string refused = [] {
        if (run({"sh", "-c", std::string("command -v ") + ESI_SOES_CC}).exit_code != 0) return std::string("no C compiler ") + ESI_SOES_CC;
        const RunResult r = run({"unshare", "-rn", "sh", "-c", "ip link add v0 type veth peer name v1 && ip link set v0 up"});
        if (r.exit_code != 0) return "user/network namespaces with a veth pair are refused here: " + r.err;
        return std::string();
    }();
    return refused;
}

SoesFirmware build_soes_firmware(const fs::path& source, const fs::path& dir, bool sanitize) {
    SoesFirmware fw;
    fw.source = source;
    fw.generated = dir / source.stem();
    LoadedDocument loaded = load_document_file(source);
    if (!loaded.usable() || loaded.document->infos.size() != 1 || loaded.document->infos[0].devices.size() != 1) {
        fw.error = source.string() + ": not a source of one device";
        return fw;
    }
    const Device& device = loaded.document->infos[0].devices[0];
    fw.type = device.type.text;
    fw.selector = fmt::format("0x{:X}:0x{:X}", device.type.product_code.value_or(0), device.type.revision_no.value_or(0));
    fw.default_assign = nlohmann::json::object();
    for (const auto& [key, pdos] : {std::pair{"7186", &device.rx_pdos}, std::pair{"7187", &device.tx_pdos}}) {
        nlohmann::json list = nlohmann::json::array();
        for (const Pdo& pdo : *pdos) {
            if (!pdo.sm) continue;
            nlohmann::json entries = nlohmann::json::array();
            for (const PdoEntry& e : pdo.entries) entries.push_back(e.index << 16 | e.subindex.value_or(0) << 8 | e.bit_len);
            list.push_back({{"pdo", pdo.index}, {"entries", entries}});
        }
        fw.default_assign[key] = list;
    }

    const RunResult gen = run({tool("esi-gen").string(), source.string(), "-o", fw.generated.string(), "--only", "soes,sii"});
    if (gen.exit_code != 0) {
        fw.error = "esi-gen: " + gen.err;
        return fw;
    }
    // An image whose ConfigData enables no PDI (PDI control 0) cannot run firmware: such samples
    // run with SPI (PDI control 0x05) and the checksum made right, as on a board with an SPI PDI.
    fw.eeprom = fw.generated / "eeprom.bin";
    {
        std::ifstream in(fw.eeprom, std::ios::binary);
        std::vector<std::uint8_t> image((std::istreambuf_iterator<char>(in)), {});
        if (image.size() < 16) {
            fw.error = "esi-gen wrote an EEPROM image of " + std::to_string(image.size()) + " bytes";
            return fw;
        }
        if (image[0] == 0) {
            image[0] = 0x05;
            image[14] = config_crc(std::span<const std::uint8_t>(image.data(), 14));
            fw.eeprom = fw.generated / "eeprom-spi.bin";
            std::ofstream out(fw.eeprom, std::ios::binary);
            out.write(reinterpret_cast<const char*>(image.data()), static_cast<std::streamsize>(image.size()));
        }
    }

    const fs::path network = dir / (source.stem().string() + "-network.yaml");
    write_text(network, fmt::format("esi: [{}]\nmaster: {{ name: Test, cycle_time_us: 1000 }}\nslaves:\n  - {{ name: S, device: {} }}\n",
                                    nlohmann::json(source.string()).dump(), nlohmann::json(fw.type).dump()));
    const RunResult net = run({tool("esi-net").string(), "build", network.string(), "-o", (dir / (source.stem().string() + "-net")).string()});
    if (net.exit_code != 0) {
        fw.error = "esi-net: " + net.err;
        return fw;
    }
    fw.process_image = nlohmann::json::parse(read_text(dir / (source.stem().string() + "-net") / "process_image.json"));

    // SOES's own warning flags (its cmake/Linux.cmake) without -Werror: the SOES core's warnings
    // depend on the compiler, and tests/codegen's SoesStack holds the generated set to them. The
    // core's files as soes/CMakeLists.txt lists them.
    fw.library = dir / (source.stem().string() + (sanitize ? "-asan.so" : ".so"));
    std::vector<std::string> argv{ESI_SOES_CC, "-shared", "-fPIC", "-g", "-O0", "-Wall", "-Wextra", "-Wconversion",
                                  "-Wno-unused-parameter"};
    if (sanitize) argv.insert(argv.end(), {"-fsanitize=address", "-fno-omit-frame-pointer"});
    for (const fs::path& d : {fw.generated, soes_core(), soes_core() / "include" / "sys" / "gcc", firmware_dir()})
        argv.push_back("-I" + d.string());
    for (const char* file : {"esc.c", "esc_coe.c", "esc_foe.c", "esc_eoe.c", "esc_eep.c", "ecat_slv.c"})
        argv.push_back((soes_core() / file).string());
    for (const fs::path& file : {fw.generated / "objectlist.c", firmware_dir() / "soes_hal.c", firmware_dir() / "soes_app.c"})
        argv.push_back(file.string());
    argv.insert(argv.end(), {"-o", fw.library.string()});
    const RunResult cc = run(argv);
    if (cc.exit_code != 0) fw.error = "cc: " + cc.err;
    if (sanitize && fw.error.empty() && !host_sanitized && asan_runtime().empty())
        fw.error = std::string("no AddressSanitizer runtime for ") + ESI_SOES_CC;
    return fw;
}

const SoesFirmware& soes_firmware(const fs::path& source, bool sanitize) {
    static TempDir dir;
    static std::map<std::pair<fs::path, bool>, SoesFirmware> built;
    const auto key = std::pair{source, sanitize};
    auto it = built.find(key);
    if (it == built.end()) {
        const fs::path sub = dir / (sanitize ? "asan" : "plain");
        fs::create_directories(sub);
        it = built.emplace(key, build_soes_firmware(source, sub, sanitize)).first;
    }
    return it->second;
}

std::vector<SoesStepResult> run_soes_session(const std::vector<SoesStep>& steps) {
    TempDir dir;
    std::ostringstream script;
    script << "ip link add v0 type veth peer name v1 && ip link set v0 up && ip link set v1 up || exit 3\n";
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const std::string out = (dir.path() / std::to_string(i)).string();
        const std::string master = steps[i].master.empty() ? std::string(ESI_SOES_MASTER) : steps[i].master;
        // Under AddressSanitizer (the firmware, or the whole host in the sanitizer tree) the leak
        // check is off: it would report the loader's one-time allocations for the dlopen'ed
        // firmware, and what these runs look for is SOES overrunning its buffers.
        std::string env;
        if (steps[i].sanitize && !host_sanitized) env = "env LD_PRELOAD=" + shell_quoted(asan_runtime()) + " ASAN_OPTIONS=detect_leaks=0 ";
        else if (host_sanitized) env = "env ASAN_OPTIONS=detect_leaks=0 ";
        script << env << shell_quoted(ESI_SOES_HOST) << " --iface v1" << shell_arguments(steps[i].host_args) << " > " << shell_quoted(out + ".host")
               << " 2> " << shell_quoted(out + ".err") << " &\n"
               << "pid=$!\n"
               << "n=0; while ! grep -q 'slave(s) on' " << shell_quoted(out + ".err")
               << " 2>/dev/null && kill -0 $pid 2>/dev/null && [ $n -lt 400 ]; do sleep 0.025; n=$((n+1)); done\n"
               << "if kill -0 $pid 2>/dev/null; then timeout 120 " << shell_quoted(master) << " v0" << shell_arguments(steps[i].master_args)
               << " > " << shell_quoted(out + ".json") << " 2> /dev/null; kill -TERM $pid; fi\n"
               << "wait $pid; echo $? > " << shell_quoted(out + ".rc") << "\n";
    }
    run({"unshare", "-rn", "sh", "-c", script.str()});
    std::vector<SoesStepResult> results(steps.size());
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const fs::path out = dir.path() / std::to_string(i);
        SoesStepResult& r = results[i];
        const auto text = [&](const std::string& ext) {
            const fs::path p = out.string() + ext;
            return fs::exists(p) ? read_text(p) : std::string();
        };
        r.host_stderr = text(".err");
        r.host_output = text(".host");
        r.master_output = text(".json");
        const std::string rc = text(".rc");
        if (!rc.empty()) r.host_exit = std::stoi(rc);
        for (const auto& [from, to] : {std::pair{&r.master_output, &r.master}, std::pair{&r.host_output, &r.host}}) {
            const auto parsed = nlohmann::json::parse(*from, nullptr, false);
            if (!parsed.is_discarded()) *to = parsed;
        }
    }
    return results;
}

std::uint64_t image_bits(const std::string& hex, std::uint32_t offset, std::uint32_t bits) {
    std::uint64_t value = 0;
    for (std::uint32_t i = 0; i < bits; ++i) {
        const std::uint32_t bit = offset + i, byte = bit / 8;
        if (2 * byte + 2 > hex.size()) break;
        const auto b = static_cast<std::uint8_t>(std::stoul(hex.substr(2 * byte, 2), nullptr, 16));
        if (b >> (bit % 8) & 1) value |= std::uint64_t{1} << i;
    }
    return value;
}

namespace {

std::uint64_t hex_number(const nlohmann::json& v) { return std::stoull(v.get<std::string>(), nullptr, 16); }

std::map<std::pair<std::uint64_t, std::uint64_t>, nlohmann::json> objects_by_index(const nlohmann::json& list) {
    std::map<std::pair<std::uint64_t, std::uint64_t>, nlohmann::json> out;
    for (const auto& o : list) out[{o["index"].get<std::uint64_t>(), o["sub"].get<std::uint64_t>()}] = o;
    return out;
}

}  // namespace

void expect_variables_match(const nlohmann::json& process_image, int position, const nlohmann::json& master,
                            const nlohmann::json& host_slave) {
    const auto outputs = objects_by_index(host_slave["outputs"]);
    const auto inputs = objects_by_index(host_slave["inputs"]);
    int checked = 0;
    for (const auto& v : process_image["variables"]) {
        if (v["position"] != position) continue;
        SCOPED_TRACE(v["name"].get<std::string>());
        const bool output = v["direction"] == "output";
        const auto& found = output ? outputs : inputs;
        const auto it = found.find({hex_number(v["index"]), hex_number(v["subindex"])});
        ASSERT_NE(it, found.end()) << "SOES has no object for the variable";
        ASSERT_TRUE(it->second.contains("value")) << "SOES never received outputs in OP";
        const auto offset = v["byte_offset"].get<std::uint32_t>() * 8 + v["bit_offset"].get<std::uint32_t>();
        const auto bits = v["bit_size"].get<std::uint32_t>();
        const std::string& image = master[output ? "outputs" : "inputs"].get_ref<const std::string&>();
        ASSERT_LE((offset + bits + 7) / 8, image.size() / 2) << "the variable lies past the master's image";
        EXPECT_EQ(image_bits(image, offset, bits), it->second["value"].get<std::uint64_t>())
            << "at bit " << offset << ", " << bits << " bits";
        ++checked;
    }
    // Only a slave without process data (the modular coupler's SOES set, which holds no
    // modules) has nothing to check.
    for (const auto& slave : process_image["slaves"])
        if (slave["position"] == position && (slave["output_bytes"] > 0 || slave["input_bytes"] > 0)) {
            EXPECT_GT(checked, 0);
        }
}

}  // namespace esi::test
