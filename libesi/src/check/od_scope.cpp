#include "check/od_scope.hpp"

namespace esi::rules {

std::vector<DictionaryScope> dictionary_scopes(const EsiDocument& document) {
    std::vector<DictionaryScope> out;
    std::size_t owners = 1;  // the document's own Dictionary
    for (const auto& info : document.infos) owners += info.devices.size() + info.modules.size();
    out.reserve(owners);  // every od rule starts with this list: one allocation for it (devices rarely have two Dictionaries)
    for (const auto& info : document.infos) {
        for (const auto& device : info.devices)
            for (const auto& profile : device.profiles)
                if (profile.dictionary) out.push_back({&*profile.dictionary, &device, nullptr});
        for (const auto& module : info.modules)
            if (module.profile && module.profile->dictionary) out.push_back({&*module.profile->dictionary, nullptr, &module});
    }
    if (document.dictionary) out.push_back({&*document.dictionary, nullptr, nullptr});
    return out;
}

}  // namespace esi::rules
