// The outline (LSP document symbols): each device or module with its SyncManagers, PDOs (and
// their entries), DataTypes and objects, in document order within each kind.

#include "navigate/format.hpp"
#include "navigate/index.hpp"

namespace esi::navigate {

namespace {

Symbol symbol(const Index& index, std::string name, std::string detail, SymbolKind kind, Span element, Span decl) {
    Symbol out;
    out.name = std::move(name);
    out.detail = std::move(detail);
    out.kind = kind;
    out.range = index.range(element);
    out.selection_range = index.range(decl);
    return out;
}

// What derivation adds to a YAML source (SMs, mapping objects, DataTypes) is not in the text.
bool written(Span element) { return !element.empty(); }

}  // namespace

std::vector<Symbol> outline(const Index& index) {
    std::vector<Symbol> symbols;
    for (const Scope& scope : index.scopes) {
        Symbol device = symbol(index, scope.type.empty() ? scope.name : scope.type, scope.name,
                               scope.module ? SymbolKind::module : SymbolKind::device, scope.element, scope.decl);
        if (device.name.empty()) device.name = scope.module ? "Module" : "Device";
        for (const SmDef& sm : scope.sms)
            if (written(sm.element))
                device.children.push_back(symbol(index, "SM" + std::to_string(sm.number), sm.role, SymbolKind::sync_manager,
                                             sm.element, sm.decl));
        for (const PdoDef& pdo : scope.pdos) {
            if (!written(pdo.element)) continue;
            Symbol entry_parent = symbol(index, std::string(pdo.tx ? "TxPdo " : "RxPdo ") + format_index(pdo.index, index.yaml),
                                         pdo.name, SymbolKind::pdo, pdo.element, pdo.decl);
            for (const PdoEntryDef& entry : pdo.entries) {
                if (!written(entry.element)) continue;
                std::string name = entry.index == 0 ? std::string("padding")
                                                    : format_index(entry.index, index.yaml) + ":" +
                                                          format_subindex(entry.subindex, index.yaml);
                entry_parent.children.push_back(symbol(index, std::move(name), entry.name, SymbolKind::pdo_entry,
                                                       entry.element, entry.decl));
            }
            device.children.push_back(std::move(entry_parent));
        }
        for (const DataTypeDef& type : scope.data_types)
            if (written(type.element))
                device.children.push_back(symbol(index, type.name, type.bit_size.empty() ? std::string() : type.bit_size + " bits",
                                             SymbolKind::data_type, type.element, type.decl));
        for (const ObjectDef& object : scope.objects)
            if (written(object.element))
                device.children.push_back(symbol(index, format_index(object.index, index.yaml), object.name, SymbolKind::object,
                                             object.element, object.decl));
        symbols.push_back(std::move(device));
    }
    return symbols;
}

}  // namespace esi::navigate
