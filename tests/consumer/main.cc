// Reads the generated tables at run time: the C tables (compiled from generated slave_tables.c
// and linked in), the constexpr C++ header and the process-image struct.

#include <cstdio>

#include "object_dictionary.hpp"
#include "process_image.h"
#include "slave_tables.h"

int main() {
    const board_od_entry_t* device_type = board_od_find_entry(0x1000, 0);
    if (device_type == nullptr) return 1;
    std::printf("device type 0x%08llX\n", static_cast<unsigned long long>(device_type->default_value.bits));
    std::printf("objects %zu\n", board_od_object_count);
    // The C++ header and the C tables come from the same view: they must agree.
    constexpr auto* entry = board::od::find_entry(0x1000, 0);
    static_assert(entry != nullptr);
    if (entry->default_value.u != device_type->default_value.bits) return 2;
    std::printf("rx image %zu bytes\n", sizeof(board_rxpdo_t));
#ifdef CONSUMER_TEMPLATE_MARK
    std::printf("template mark %d\n", CONSUMER_TEMPLATE_MARK);
#endif
    return 0;
}
