#pragma once
// Umbrella header for the typed ESI model.
#include "esi/model/common.hpp"
#include "esi/model/dc.hpp"
#include "esi/model/device.hpp"
#include "esi/model/dictionary.hpp"
#include "esi/model/eeprom.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/model/mailbox.hpp"
#include "esi/model/module.hpp"
#include "esi/model/object_layout.hpp"
#include "esi/model/pdo.hpp"
#include "esi/model/sync_manager.hpp"
#include "esi/model/vendor.hpp"
