#include "sim_esc/wireshark_check.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "support/test_support.hpp"

namespace esi::test {

namespace {

void put(std::ofstream& out, std::uint32_t v) {
    const char b[4] = {static_cast<char>(v), static_cast<char>(v >> 8), static_cast<char>(v >> 16), static_cast<char>(v >> 24)};
    out.write(b, 4);
}
void put16(std::ofstream& out, std::uint16_t v) {
    const char b[2] = {static_cast<char>(v), static_cast<char>(v >> 8)};
    out.write(b, 2);
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) out.push_back(line);
    return out;
}

void write_pcap_file(const std::filesystem::path& path, const std::vector<CapturedFrame>& frames) {
    std::ofstream out(path, std::ios::binary);
    // The pcap global header: magic, version 2.4, zone 0, accuracy 0, snap length, Ethernet.
    put(out, 0xA1B2C3D4);
    put16(out, 2);
    put16(out, 4);
    put(out, 0);
    put(out, 0);
    put(out, 65535);
    put(out, 1);
    for (const CapturedFrame& f : frames) {
        std::vector<std::uint8_t> ethernet = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF,   // broadcast, as masters send
                                              0x02, 0x00, 0x00, 0x00, 0x00, 0x01,   // locally administered
                                              0x88, 0xA4};
        // An ESC sets the second address bit of the source on the way back (ESC datasheet, "Frame
        // processing"); here the source already has it, so both directions carry the same one.
        ethernet.insert(ethernet.end(), f.payload.begin(), f.payload.end());
        if (ethernet.size() < 60) ethernet.resize(60, 0);
        put(out, static_cast<std::uint32_t>(f.time_ns / 1'000'000'000));
        put(out, static_cast<std::uint32_t>(f.time_ns % 1'000'000'000 / 1000));
        put(out, static_cast<std::uint32_t>(ethernet.size()));
        put(out, static_cast<std::uint32_t>(ethernet.size()));
        out.write(reinterpret_cast<const char*>(ethernet.data()), static_cast<std::streamsize>(ethernet.size()));
    }
}

}  // namespace

void write_pcap(const std::filesystem::path& path, const std::vector<CapturedFrame>& frames) {
    write_pcap_file(path, frames);
    if (const char* keep = std::getenv("ESI_KEEP_CAPTURES"); keep && *keep)
        write_pcap_file(std::filesystem::path(keep) / path.filename(), frames);
}

bool have_tshark() {
    static const bool present = run({"/bin/sh", "-c", "command -v tshark"}).exit_code == 0;
    return present;
}

TsharkDecoding tshark_decode(const std::filesystem::path& pcap) {
    TsharkDecoding d;
    const RunResult all = run({"tshark", "-n", "-r", pcap.string(), "-T", "fields", "-e", "frame.number", "-e", "frame.protocols"});
    d.exit_code = all.exit_code;
    d.error = all.err;
    for (const std::string& line : lines(all.out)) {
        ++d.frames;
        if (line.find("ecatf") != std::string::npos) ++d.ethercat_frames;
    }
    const RunResult bad = run({"tshark", "-n", "-r", pcap.string(), "-Y", "_ws.malformed || _ws.expert.severity >= \"Error\"",
                               "-T", "fields", "-e", "frame.number", "-e", "_ws.col.Info", "-e", "_ws.expert.message"});
    if (bad.exit_code != 0) {
        d.exit_code = bad.exit_code;
        d.error += bad.err;
    }
    for (const std::string& line : lines(bad.out)) d.malformed.push_back("frame " + line);
    return d;
}

std::vector<std::string> tshark_fields(const std::filesystem::path& pcap, const std::string& filter,
                                       const std::vector<std::string>& fields) {
    std::vector<std::string> argv = {"tshark", "-n", "-r", pcap.string(), "-Y", filter, "-T", "fields"};
    for (const std::string& f : fields) argv.insert(argv.end(), {"-e", f});
    return lines(run(argv).out);
}

}  // namespace esi::test
