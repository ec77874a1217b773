#pragma once
// The SII image builder (build.cpp): one Builder per build, from a device of an ESI file to an
// Image and its bytes (ETG.2010). Its parts live in two files: build.cpp (the header words, the
// Strings category, the order of the categories, the EEPROM size, and fitting the image to it)
// and build_categories.cpp (the categories built from the device: General, FMMU, SyncM, DC,
// TxPDO/RxPDO, and the ESI's own Eeprom/Category entries).

#include <fmt/format.h>

#include <map>
#include <string>
#include <vector>

#include "esi/sii/build.hpp"

namespace esi::sii::build_detail {

class Builder {
public:
    Builder(const EtherCATInfo& info, const Device& device, const BuildOptions& options, const Omissions& omitted,
            const std::string& path, BuildResult& result)
        : info_(info), device_(device), options_(options), omitted_(omitted), path_(path), result_(result) {}

    void run();

private:
    Diagnostic& diag(Severity severity, std::string rule, std::string message, SourcePos pos) {
        return result_.diagnostics.emplace(severity, std::move(rule), std::move(message), path_, pos);
    }

    // Value -> field of `bits` bits; an error (never a silent truncation) when it does not fit.
    std::uint64_t fit_unsigned(std::int64_t value, unsigned bits, std::string_view what, SourcePos pos) {
        const std::uint64_t max = bits >= 64 ? ~0ull : ((1ull << bits) - 1);
        if (value < 0 || static_cast<std::uint64_t>(value) > max) {
            diag(Severity::error, "sii-value-range",
                 fmt::format("{} is {}; the SII field holds {}-bit unsigned values (0..{})", what, value, bits, max), pos);
            return static_cast<std::uint64_t>(value) & max;
        }
        return static_cast<std::uint64_t>(value);
    }
    std::int64_t fit_signed(std::int64_t value, unsigned bits, std::string_view what, SourcePos pos) {
        const std::int64_t max = (std::int64_t{1} << (bits - 1)) - 1;
        const std::int64_t min = -max - 1;
        if (value < min || value > max)
            diag(Severity::error, "sii-value-range",
                 fmt::format("{} is {}; the SII field holds {}-bit signed values ({}..{})", what, value, bits, min, max), pos);
        return value;
    }
    // Shift times are signed in the ESI (ns) and stored as 32 bits: accept both ranges.
    std::uint32_t fit_time(std::int64_t value, std::string_view what, SourcePos pos) {
        if (value < INT32_MIN || value > static_cast<std::int64_t>(UINT32_MAX))
            diag(Severity::error, "sii-value-range",
                 fmt::format("{} is {} ns; the SII field holds 32 bits", what, value), pos);
        return static_cast<std::uint32_t>(static_cast<std::uint64_t>(value) & 0xFFFFFFFFu);
    }

    std::uint8_t add_string(std::string_view utf8, SourcePos pos, std::string_view what);
    const std::string& localized(const Names& names) const {
        if (const LocalizedText* t = find_lcid(names, options_.name_lcid)) return t->text;
        return primary_text(names);
    }

    void build_header();
    void build_copied_categories();
    General build_general();
    void build_fmmus();
    void build_sync_managers();
    std::optional<DcOpModes> build_dc();
    Pdos build_pdos(const std::vector<Pdo>& pdos);
    void finish();
    static bool is_generated(std::uint16_t type);
    // Appends a generated category, or the explicit Eeprom/Category of that type instead.
    void add_category(std::uint16_t type, CategoryContent content);

    const EtherCATInfo& info_;
    const Device& device_;
    const BuildOptions& options_;
    const Omissions& omitted_;
    const std::string& path_;
    BuildResult& result_;
    Image& image_ = result_.image;

    std::vector<std::string> strings_;
    std::map<std::string, std::uint8_t, std::less<>> string_index_;
    std::size_t distinct_strings_ = 0;
    SourcePos first_overflow_pos_;
    std::map<std::uint16_t, Category> explicit_;  // Eeprom/Category entries of generated types
};

}  // namespace esi::sii::build_detail
