#pragma once
// The Dictionaries of a document, with their owners: every Profile/Dictionary of every device,
// the Dictionary of every module, and the root Dictionary of an EtherCATDict file.

#include <vector>

#include "esi/model/ethercat_info.hpp"

namespace esi::rules {

struct DictionaryScope {
    const Dictionary* dictionary = nullptr;
    const Device* device = nullptr;  // set for a device's Profile/Dictionary
    const Module* module = nullptr;  // set for a module's Profile/Dictionary
};

[[nodiscard]] std::vector<DictionaryScope> dictionary_scopes(const EsiDocument& document);

}  // namespace esi::rules
