#pragma once
// Optional validation against the ETG XML schema files (libxml2). Schema errors become
// xml-schema diagnostics with line numbers.

#include <filesystem>
#include <memory>
#include <string>

#include "esi/diagnostic.hpp"
#include "esi/source_text.hpp"

namespace esi {

class SchemaSet {
public:
    // Loads EtherCATInfo.xsd, EtherCATModule.xsd and EtherCATDict.xsd where present in `dir`.
    static std::shared_ptr<SchemaSet> load(const std::filesystem::path& dir, Diagnostics& diagnostics);
    ~SchemaSet();
    SchemaSet(const SchemaSet&) = delete;
    SchemaSet& operator=(const SchemaSet&) = delete;

    // Validates UTF-8 text against the schema for its root element. Thread-safe.
    [[nodiscard]] Diagnostics validate(const SourceText& source) const;

private:
    SchemaSet() = default;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace esi
