#include "check/od_scope.hpp"

namespace esi::rules {

std::vector<DictionaryScope> dictionary_scopes(const EsiDocument& document) {
    std::vector<DictionaryScope> out;
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
