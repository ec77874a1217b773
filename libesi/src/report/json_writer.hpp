#pragma once
// JSON written straight into a string, byte for byte as nlohmann::json's dump(2) writes it with
// error_handler_t::replace (two-space indentation, "key": value, [] and {} when empty, control
// characters escaped, UTF-8 kept, invalid UTF-8 replaced by U+FFFD), which the reports were
// written with before: building an ordered_json tree of every finding and dumping it cost 50,000
// instructions a finding, most of esi-lint's time after the rules (docs/performance.md).
// tests/lint/json_writer_test.cpp holds the two to the same bytes.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace esi::report {

class JsonWriter {
public:
    void begin_object() { open('{'); }
    void end_object() { close('}'); }
    void begin_array() { open('['); }
    void end_array() { close(']'); }
    // An object member's name; its value follows.
    void key(std::string_view name);
    void value(std::string_view text);
    void value(const char* text) { value(std::string_view(text)); }
    void value(std::uint64_t number);
    void null();

    // Shorthands for a member with a value.
    template <class T>
    void member(std::string_view name, const T& v) {
        key(name);
        value(v);
    }

    [[nodiscard]] const std::string& text() const { return out_; }
    std::string take() { return std::move(out_); }

private:
    void open(char bracket);
    void close(char bracket);
    void before_value();  // the separator and indentation an array element needs
    void indent();
    void escaped(std::string_view text);

    std::string out_;
    std::vector<std::uint32_t> counts_;  // members or elements written so far, per open container
    bool after_key_ = false;
};

}  // namespace esi::report
