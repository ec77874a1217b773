#pragma once
// The ESI XML reader's shared context: one Reader per document reads the element tree of
// xml/tree_parser.hpp; its element readers live in one file per concept, as the writer's do:
// reader.cpp (document, EtherCATInfo, vendor, groups, unknown elements kept verbatim),
// reader_device.cpp (device, SyncManagers, FMMUs, PDOs, Dc, Eeprom), reader_mailbox.cpp (mailbox
// protocols and InitCmds), reader_dictionary.cpp (profiles and object dictionaries),
// reader_modules.cpp (modules and slots). The scalar readers below (numbers, booleans, hex data,
// names) are defined here so that every file inlines them: they run for nearly every attribute of
// a file.

#include <algorithm>
#include <array>
#include <cstdint>
#include <cctype>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "esi/model/mailbox_flags.hpp"
#include "esi/number.hpp"
#include "esi/source_text.hpp"
#include "esi/xml/reader.hpp"
#include "xml/element_tree.hpp"
#include "xml/tree_parser.hpp"

namespace esi::xml_reader {

using xml_tree::Element;
using Attr = xml_tree::Attribute;

// Element and attribute names are compared with literals about ten times per element. This
// compares the length, then a memcmp whose length is known at compile time, which the compiler
// turns into a load or two, where string_view's operator== is an out-of-line call plus a memcmp
// call. (always_inline: GCC otherwise keeps some instances out of line, a call per compare.)
template <std::size_t N>
[[gnu::always_inline]] inline bool is(std::string_view name, const char (&literal)[N]) {
    return name.size() == N - 1 && std::memcmp(name.data(), literal, N - 1) == 0;
}

class Reader {
public:
    // `parser` has read the root's start tag of `source`'s text; the reader streams the rest.
    Reader(const SourceText& source, xml_tree::TreeParser& parser, Diagnostics& diagnostics, const ReadOptions& options)
        : source_(source), parser_(parser), text_(source.text()), diagnostics_(diagnostics), options_(options) {}

    EsiDocument read_document(const Element root);

private:
    // ---- positions and diagnostics ------------------------------------------------------
    // Where an element starts: the '<' before its name (the parser computed it).
    static SourcePos pos_of(const Element element) { return element.pos(); }
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);
    // The offset in the text of a name or value; npos for a value that is not in the text (it
    // was decoded: it held a reference or a line break).
    std::size_t offset_of(const char* text) const {
        const auto at = reinterpret_cast<std::uintptr_t>(text);
        const auto begin = reinterpret_cast<std::uintptr_t>(text_.data());
        return at >= begin && at < begin + text_.size() ? at - begin : npos;
    }

    Diagnostic& report(Severity severity, std::string rule, std::string message, SourcePos pos) {
        return diagnostics_.emplace(severity, std::move(rule), std::move(message), source_.path(), pos);
    }
    // A safe fix replacing `length` bytes at `at`, a pointer into a value; none when the value is
    // not the file's text as written (a decoded value).
    std::optional<Fix> fix_at(const char* at, std::size_t length, std::string replacement, std::string description) const {
        const std::size_t offset = offset_of(at);
        if (offset == npos || offset + length > source_.text().size()) return std::nullopt;
        if (source_.text().compare(offset, length, at, length) != 0) return std::nullopt;
        return Fix{std::move(description), {TextEdit{offset, length, std::move(replacement)}}};
    }
    // The safe fixes of a hex number's spelling: 0x… → #x… (xml-hex-prefix) and #x0x… → #x…
    // (xml-number-format, only when hex digits follow, so that the result reads).
    std::optional<Fix> hex_prefix_fix(std::string_view text) const {
        const std::string_view t = trim(text);
        const std::size_t sign = !t.empty() && (t[0] == '+' || t[0] == '-') ? 1 : 0;
        if (t.size() > sign + 2 && t[sign] == '0' && (t[sign + 1] == 'x' || t[sign + 1] == 'X'))
            return fix_at(t.data() + sign, 2, "#x", "write #x for 0x");
        return std::nullopt;
    }
    std::optional<Fix> double_prefix_fix(std::string_view text) const {
        const std::string_view t = trim(text);
        if (t.size() <= 4 || t[0] != '#' || t[1] != 'x' || t[2] != '0' || (t[3] != 'x' && t[3] != 'X')) return std::nullopt;
        for (const char c : t.substr(4))
            if (!std::isxdigit(static_cast<unsigned char>(c))) return std::nullopt;
        return fix_at(t.data() + 2, 2, "", "drop the second hex prefix");
    }

    // ---- scalar values -------------------------------------------------------------------
    // An element's character data: its own text, or the first text after a child or a CDATA section.
    static std::string_view pcdata(const Element n) { return n.text(); }
    static std::string text_of(const Element node) { return std::string(trim(pcdata(node))); }
    // The same into a field, in place (no temporary string moved in).
    // Sets a string of the model. Nearly every one is set once, while empty: appending to it is
    // the short way through the library (assign() takes its general path for a replacement,
    // some 80 instructions before the copy, and the reader sets some 400,000 strings per corpus).
    static void set(std::string& field, std::string_view value) {
        if (field.empty()) field.append(value.data(), value.size());
        else field.assign(value.data(), value.size());
    }
    static void text(std::string& field, const Element node) { set(field, trim(pcdata(node))); }
    static void text(std::optional<std::string>& field, const Element node) { field.emplace(trim(pcdata(node))); }
    static void text(RareOptional<std::string>& field, const Element node) { field.emplace(trim(pcdata(node))); }

    // Where a scalar was read from: named ("Sm@StartAddress", or the element's name) and located
    // only when the value is bad, so that a good value costs no string allocation and no
    // position lookup.
    struct ValueSite {
        Element element;
        const Attr* attribute = nullptr;
        std::string_view label = {};  // used instead of the element/attribute names when set
    };
    static std::string describe(const ValueSite& site) {
        if (!site.label.empty()) return std::string(site.label);
        if (site.attribute) return std::string(site.element.name()) + "@" + std::string(site.attribute->name);
        return std::string(site.element.name());
    }

    // Nearly every number of a file is plain decimal or #x hex digits, few enough not to overflow
    // (16 at most), without sign or blanks: read here, inline; everything else (and every fault)
    // goes through parse_number and is reported by checked_number().
    static bool plain_number(std::string_view text, std::uint64_t& value) {
        if (text.empty() || text.size() > 16) return false;
        const char* p = text.data();
        const char* const end = p + text.size();
        std::uint64_t v = 0;
        if (p[0] == '#' && text.size() > 2 && p[1] == 'x') {
            for (p += 2; p < end; ++p) {
                const unsigned digit = hex_digit_values[static_cast<unsigned char>(*p)];
                if (digit > 15) return false;
                v = v * 16 + digit;
            }
        } else {
            for (; p < end; ++p) {
                const unsigned digit = static_cast<unsigned char>(*p) - unsigned{'0'};
                if (digit > 9) return false;
                v = v * 10 + digit;
            }
        }
        value = v;
        return true;
    }
    std::optional<Number> number(std::string_view text, const ValueSite& site) {
        std::uint64_t value = 0;
        if (plain_number(text, value)) return Number{value, false};
        return checked_number(text, site);
    }
    [[gnu::noinline]] std::optional<Number> checked_number(std::string_view text, const ValueSite& site) {
        const ParsedNumber parsed = parse_number(text);
        if (!parsed.ok()) {
            report(Severity::error, "xml-number-format",
                   describe(site) + ": '" + excerpt(trim(text)) + "' is not a number" +
                       // The reason only where it adds to "not a number" (not "(not a number)").
                       (parsed.error == NumberError::bad_digit ? std::string() : " (" + std::string(to_string(parsed.error)) + ")") +
                       "; ESI numbers are decimal or #x hex",
                   pos_of(site.element))
                .fix = double_prefix_fix(text);
            return std::nullopt;
        }
        if (parsed.syntax == NumberSyntax::c_hex) {
            report(Severity::warning, "xml-hex-prefix",
                   describe(site) + ": '" + excerpt(trim(text)) + "' uses the C prefix 0x; ESI hex numbers are written #x",
                   pos_of(site.element))
                .fix = hex_prefix_fix(text);
        }
        return parsed.value;
    }
    std::optional<Number> number(const Element n) { return number(pcdata(n), ValueSite{n}); }

    // A plain number in range is the common case, and costs no optional<Number>.
    template <class T>
    std::optional<T> integer(std::string_view text, const ValueSite& site) {
        std::uint64_t value = 0;
        if (plain_number(text, value) && value <= static_cast<std::uint64_t>(std::numeric_limits<T>::max())) return static_cast<T>(value);
        return checked_integer<T>(text, site);
    }
    template <class T>
    [[gnu::noinline]] std::optional<T> checked_integer(std::string_view text, const ValueSite& site) {
        const std::optional<Number> n = number(text, site);
        if (!n) return std::nullopt;
        if constexpr (std::is_signed_v<T>) {
            const auto v = n->as_int64();
            if (!v || *v < std::numeric_limits<T>::min() || *v > std::numeric_limits<T>::max()) {
                report(Severity::error, "xml-number-range", describe(site) + ": " + format_decimal(*n) + " is out of range",
                       pos_of(site.element));
                return std::nullopt;
            }
            return static_cast<T>(*v);
        } else {
            const auto v = n->as_uint64();
            if (!v || *v > std::numeric_limits<T>::max()) {
                report(Severity::error, "xml-number-range",
                       describe(site) + ": " + format_decimal(*n) + " is out of range (0.." +
                           std::to_string(std::numeric_limits<T>::max()) + ")",
                       pos_of(site.element));
                return std::nullopt;
            }
            return static_cast<T>(*v);
        }
    }

    std::optional<std::uint32_t> u32(const Attr& a, const Element owner) { return integer<std::uint32_t>(a.value, ValueSite{owner, &a}); }
    std::optional<std::int32_t> i32(const Attr& a, const Element owner) { return integer<std::int32_t>(a.value, ValueSite{owner, &a}); }
    std::optional<std::uint32_t> u32(const Element n) { return integer<std::uint32_t>(pcdata(n), ValueSite{n}); }
    std::optional<std::int32_t> i32(const Element n) { return integer<std::int32_t>(pcdata(n), ValueSite{n}); }
    std::optional<std::int64_t> i64(const Element n) { return integer<std::int64_t>(pcdata(n), ValueSite{n}); }
    std::optional<std::uint64_t> u64(const Element n) { return integer<std::uint64_t>(pcdata(n), ValueSite{n}); }

    std::optional<bool> boolean(std::string_view text, const ValueSite& site) {
        const auto b = parse_boolean(text);
        if (!b)
            report(Severity::error, "xml-boolean-format",
                   describe(site) + ": '" + excerpt(trim(text)) + "' is not a boolean (true, false, 1 or 0)", pos_of(site.element));
        return b;
    }
    std::optional<bool> boolean(const Attr& a, const Element owner) { return boolean(a.value, ValueSite{owner, &a}); }
    std::optional<bool> boolean(const Element n) { return boolean(pcdata(n), ValueSite{n}); }

    HexData hex(const Element n) {
        HexData out;
        out.pos = pos_of(n);
        const std::string_view raw = trim(pcdata(n));
        const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
        // Hex data is almost never split over lines. The test for a blank is two compares per
        // byte (only bytes up to ' ' can be one), where find_first_of(" \t\n\r") searches the
        // set for every byte, some 500 instructions per DefaultData.
        if (std::none_of(raw.begin(), raw.end(), [&](char c) { return static_cast<unsigned char>(c) <= ' ' && is_space(c); })) {
            set(out.text, raw);
            return out;
        }
        out.text.reserve(raw.size());
        for (char c : raw)
            if (!is_space(c)) out.text.push_back(c);
        return out;
    }

    // A Name, Comment, URL ... with its LcId, appended to `texts`.
    void localized(Names& texts, const Element n) {
        LocalizedText& t = texts.emplace_back();
        text(t.text, n);
        t.pos = pos_of(n);
        for (const Attr& a : n.attributes()) {
            if (is(a.name, "LcId")) t.lcid = integer<std::uint32_t>(a.value, ValueSite{n, &a, "LcId"});
        }
    }

    // DependOnSlot and DependOnSlotGroup of an Index or Exclude element (ETG.2000 Slots: the
    // index is raised by the slot's or the slot group's increment for each instance). Every other
    // attribute goes to `other`; without one they are dropped, as the writer writes these two only.
    template <class Other>
    void depend_on_slot(const Element n, std::optional<bool>& on_slot, std::optional<bool>& on_slot_group, Other&& other) {
        for (const Attr& a : n.attributes()) {
            const std::string_view an = a.name;
            if (is(an, "DependOnSlot")) on_slot = boolean(a, n);
            else if (is(an, "DependOnSlotGroup")) on_slot_group = boolean(a, n);
            else other(a);
        }
    }
    void depend_on_slot(const Element n, std::optional<bool>& on_slot, std::optional<bool>& on_slot_group) {
        depend_on_slot(n, on_slot, on_slot_group, [](const Attr&) {});
    }

    // ---- verbatim store ------------------------------------------------------------------
    void verbatim(XmlElement& e, const Element n, std::string_view after, std::size_t depth);

    void keep(Extras& extras, const Element n, std::string_view after) {
        verbatim(extras.elements.emplace_back(), n, after, 1);
    }
    static void keep(Extras& extras, const Attr& a) { extras.attributes.push_back({std::string(a.name), std::string(a.value)}); }

    // Iterates element children, tracking the name of the previous element for Extras.after.
    // The children that are not elements (character data after a child, CDATA sections) are
    // skipped.
    template <class F>
    static void for_children(const Element n, F&& f) {
        std::string_view previous;
        for (Element c = n.first_child(); c; c = c.next_sibling()) {
            if (c.kind() != xml_tree::NodeKind::element) continue;
            const std::string_view name = c.name();
            f(c, name, previous);
            previous = name;
        }
    }

    // The same for an element whose content is not read yet (the root, and the elements that hold
    // a catalogue's devices and modules): each child is read from the text in turn and dropped
    // once `f` has it in the model, so that a catalogue is never in memory as a whole. `f` reads a
    // child with expanded() or streams it further with stream_children().
    template <class F>
    void stream_children(const Element n, F&& f) {
        parser_.stream_children(n, f);
    }
    // Reads the rest of an element handed out by stream_children: false after a fault, and then
    // the element must not be read.
    bool expanded(const Element n) { return parser_.expand(n); }

    // Reserves room for the children named `name` about to be read into `items`: large model
    // elements (an Object is about 1 KB) are then neither moved while the vector grows nor
    // left with up to half of its capacity unused.
    // The name is a literal, compared inline (this walks every child of every Object/Info and PDO).
    template <class T, std::size_t N>
    static void reserve_for(std::vector<T>& items, const Element n, const char (&name)[N]) {
        std::size_t count = 0;
        for (Element c = n.first_child(); c; c = c.next_sibling()) count += c.kind() == xml_tree::NodeKind::element && is(c.name(), name);
        items.reserve(items.size() + count);
    }

    void missing(std::string_view parent, std::string_view child, SourcePos pos) {
        report(Severity::error, "xml-missing-element", std::string(parent) + " has no " + std::string(child) + " element", pos);
    }

    // ---- model elements ------------------------------------------------------------------
    // reader.cpp
    void read_info(EtherCATInfo& out, const Element n);
    void read_modules(EtherCATInfo& out, const Element n);
    void read_vendor(Vendor& out, const Element n);
    void read_group(Group& out, const Element n);
    bool read_image(Images& images, const Element c, std::string_view name);
    // reader_device.cpp
    void read_device(Device& out, const Element n);
    void read_identity(DeviceIdentity& out, const Element n);
    void read_sm(SyncManager& out, const Element n);
    void read_fmmu(Fmmu& out, const Element n);
    void read_su(SyncUnit& out, const Element n);
    void read_pdo(Pdo& out, const Element n, PdoDirection direction);
    void read_entry(PdoEntry& out, const Element n);
    void read_dc(Dc& out, const Element n);
    void read_op_mode(DcOpMode& out, const Element n);
    DcTime read_dc_time(const Element n);
    void read_eeprom(Eeprom& out, const Element n);
    // reader_mailbox.cpp
    void read_mailbox(Mailbox& out, const Element n);
    void read_init_cmd(InitCmd& out, const Element n);
    template <class Protocol, std::size_t N, class Attribute>
    void read_protocol(Protocol& out, const Element n, const MailboxFlag<Protocol> (&flags)[N], Attribute&& attribute);
    // reader_dictionary.cpp
    void read_profile(Profile& out, const Element n);
    void read_dictionary(Dictionary& out, const Element n);
    void read_data_type(DataType& out, const Element n);
    void read_type_sub_item(DataTypeSubItem& out, const Element n);
    void read_object(Object& out, const Element n);
    void read_object_info(ObjectInfo& out, const Element n, std::size_t depth);
    void read_flags(ObjectFlags& out, const Element n);
    // reader_modules.cpp
    void read_module(Module& out, const Element n);
    void read_slots(Slots& out, const Element n);
    void read_slot(Slot& out, const Element n);

    const SourceText& source_;
    xml_tree::TreeParser& parser_;
    std::string_view text_;
    Diagnostics& diagnostics_;
    const ReadOptions& options_;
    bool depth_reported_ = false;
};

}  // namespace esi::xml_reader
